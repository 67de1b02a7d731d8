/*
 * Test of the C interface (include/interphase.h).
 *
 *   test_capi <mixed.csv>
 *
 * 1. Replays the paper's mixed history (2-D) through interphase_update, row by row of the
 *    driver's reference CSV (tests/driver/reference/mixed.csv, written by the Fortran UMAT path),
 *    and compares traction, damage, slip, regime and stored energy with it.
 * 2. Closed forms along the way: elastic rows t = K s; once D = 1 every slipping row has
 *    |Sigma_T| = mu |Sigma_N|; D never decreases.
 * 3. The row-major tangent equals a finite-difference tangent of interphase_update (on a
 *    slipping row, where it is unsymmetric, so a transposed matrix would fail).
 * 4. Failures: a bad PROPS value, a bad ntens and a NaN separation return the right status and
 *    message and leave the outputs untouched; interphase_status_message truncates like snprintf.
 *
 * Exits 0 when every check passes, 1 otherwise, printing each failed check.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "interphase.h"

static int failures = 0;
static int checks = 0;

#define CHECK(cond, ...)                                   \
  do {                                                     \
    ++checks;                                              \
    if (!(cond)) {                                         \
      ++failures;                                          \
      fprintf(stderr, "FAILED %s:%d: ", __FILE__, __LINE__); \
      fprintf(stderr, __VA_ARGS__);                        \
      fprintf(stderr, "\n");                               \
    }                                                      \
  } while (0)

/* The paper's Table 1 data, mu = 0.75 (our assumption), K from the laminate closed forms. */
static const double K_N = 544000.0 / 1127.0; /* MPa/mm */
static const double K_T = 32000.0 / 161.0;   /* MPa/mm */
static const double MU = 0.75;

static void paper_props(double props[INTERPHASE_NPROPS_SIMPLIFIED]) {
  const double p[INTERPHASE_NPROPS_SIMPLIFIED] = {1.0, 1.0, MU, 0.00044, 0.04, 0.00072, 0.06, K_N, K_T};
  memcpy(props, p, sizeof p);
}

/* |a - b| <= abs_tol + rel_tol |b| */
static int close_to(double a, double b, double abs_tol, double rel_tol) {
  return fabs(a - b) <= abs_tol + rel_tol * fabs(b);
}

static int regime_code(const char *name) {
  if (strcmp(name, "intact") == 0) return 0;
  if (strcmp(name, "open") == 0) return 1;
  if (strcmp(name, "stick") == 0) return 2;
  if (strcmp(name, "slip") == 0) return 3;
  return -1;
}

/* Central finite-difference tangent of the update at fixed old state, row-major. */
static void fd_tangent(const double *props, const double *state_old, const double *s, double *fd) {
  const double h = 1.0e-8;
  for (int j = 0; j < 2; ++j) {
    double sp[2] = {s[0], s[1]}, sm[2] = {s[0], s[1]};
    double tp[2], tm[2], k[4], st[INTERPHASE_NSTATE], psi;
    sp[j] += h;
    sm[j] -= h;
    interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state_old, sp, tp, k, st, &psi, NULL, 0);
    interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state_old, sm, tm, k, st, &psi, NULL, 0);
    for (int i = 0; i < 2; ++i) fd[i * 2 + j] = (tp[i] - tm[i]) / (2.0 * h);
  }
}

static void test_mixed_history(const char *csv_path) {
  FILE *f = fopen(csv_path, "r");
  CHECK(f != NULL, "cannot open %s", csv_path);
  if (f == NULL) return;
  char header[256];
  CHECK(fgets(header, sizeof header, f) != NULL && strncmp(header, "t,s_T,s_N,Sigma_T,Sigma_N,D,slip,state,psi", 42) == 0,
        "unexpected CSV header in %s", csv_path);

  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  double state[INTERPHASE_NSTATE] = {0.0, 0.0, 0.0, 0.0};
  int rows = 0, elastic_rows = 0, coulomb_rows = 0, tangent_checked = 0;
  double t, s_t, s_n, sig_t, sig_n, d, slip, psi_ref, w_dis;
  char regime[32];
  while (fscanf(f, " %lf,%lf,%lf,%lf,%lf,%lf,%lf,%31[^,],%lf,%lf", &t, &s_t, &s_n, &sig_t, &sig_n, &d, &slip,
                regime, &psi_ref, &w_dis) == 10) {
    ++rows;
    const double s[2] = {s_n, s_t};
    double traction[2], tangent[4], state_new[INTERPHASE_NSTATE], psi;
    char detail[256] = "";
    int status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s, traction, tangent, state_new, &psi,
                                   detail, sizeof detail);
    CHECK(status == INTERPHASE_STATUS_OK, "row %d (t = %g): status %d: %s", rows, t, status, detail);
    if (status != INTERPHASE_STATUS_OK) break;

    /* the Fortran UMAT path, as the driver wrote it */
    CHECK(close_to(traction[0], sig_n, 1e-12, 1e-9), "row %d: Sigma_N %.17g, reference %.17g", rows, traction[0], sig_n);
    CHECK(close_to(traction[1], sig_t, 1e-12, 1e-9), "row %d: Sigma_T %.17g, reference %.17g", rows, traction[1], sig_t);
    CHECK(close_to(state_new[0], d, 1e-12, 1e-9), "row %d: D %.17g, reference %.17g", rows, state_new[0], d);
    CHECK(close_to(state_new[1], slip, 1e-12, 1e-9), "row %d: slip %.17g, reference %.17g", rows, state_new[1], slip);
    CHECK(close_to(psi, psi_ref, 1e-12, 1e-9), "row %d: psi %.17g, reference %.17g", rows, psi, psi_ref);
    CHECK((int)state_new[3] == regime_code(regime), "row %d: regime %g, reference %s", rows, state_new[3], regime);

    /* closed forms */
    CHECK(state_new[0] >= state[0], "row %d: damage decreased from %g to %g", rows, state[0], state_new[0]);
    if (state_new[0] == 0.0) {
      ++elastic_rows;
      CHECK(close_to(traction[0], K_N * s_n, 0.0, 1e-14) && close_to(traction[1], K_T * s_t, 0.0, 1e-14),
            "row %d: intact traction (%g, %g) is not K s", rows, traction[0], traction[1]);
      CHECK(close_to(psi, 0.5 * (traction[0] * s_n + traction[1] * s_t), 0.0, 1e-14), "row %d: intact psi %g", rows, psi);
    }
    if (state_new[0] == 1.0 && (int)state_new[3] == 3) {
      ++coulomb_rows;
      CHECK(close_to(fabs(traction[1]), MU * fabs(traction[0]), 1e-14, 1e-12),
            "row %d: |Sigma_T| = %.17g but mu |Sigma_N| = %.17g", rows, fabs(traction[1]), MU * fabs(traction[0]));
      if (tangent_checked < 3 && state[0] == 1.0) { /* away from the kink where D reaches 1 */
        /* row-major: tangent[1*2+0] = dSigma_T/ds_N = mu K_N sign (nonzero), tangent[0*2+1] = 0 */
        double fd[4];
        fd_tangent(props, state, s, fd);
        for (int k = 0; k < 4; ++k)
          CHECK(close_to(tangent[k], fd[k], 1e-6, 1e-6), "row %d: tangent[%d] = %.10g, finite difference %.10g", rows, k,
                tangent[k], fd[k]);
        CHECK(tangent[0 * 2 + 1] == 0.0 && fabs(tangent[1 * 2 + 0]) > 1.0,
              "row %d: tangent not row-major: dSigma_N/ds_T = %g, dSigma_T/ds_N = %g", rows, tangent[1], tangent[2]);
        ++tangent_checked;
      }
    }
    memcpy(state, state_new, sizeof state);
  }
  fclose(f);
  CHECK(rows > 1000, "only %d rows read from %s", rows, csv_path);
  CHECK(elastic_rows > 10, "only %d intact rows", elastic_rows);
  CHECK(coulomb_rows > 100, "only %d rows slipping at D = 1", coulomb_rows);
  CHECK(tangent_checked == 3, "tangent checked on %d rows", tangent_checked);
  printf("mixed history: %d rows, %d intact, %d slipping at D = 1\n", rows, elastic_rows, coulomb_rows);
}

static void test_failures(void) {
  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  const double state[INTERPHASE_NSTATE] = {0.0, 0.0, 0.0, 0.0};
  const double s[3] = {0.001, 0.0005, 0.0};
  double traction[3] = {-7.0, -7.0, -7.0}, tangent[9] = {-7.0}, state_new[INTERPHASE_NSTATE] = {-7.0}, psi = -7.0;
  char detail[256], msg[256];

  /* bad PROPS value: sf_N < s0_N */
  props[4] = 0.0001;
  int status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s, traction, tangent, state_new, &psi,
                                 detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_SF_N, "bad sf_N: status %d, expected %d", status, INTERPHASE_STATUS_BAD_SF_N);
  CHECK(strstr(detail, "PROPS(5) sf_N") != NULL, "bad sf_N: detail \"%s\"", detail);
  interphase_status_message(status, msg, sizeof msg);
  CHECK(strcmp(msg, "full-crack normal separation sf_N out of range") == 0, "bad sf_N: message \"%s\"", msg);
  CHECK(traction[0] == -7.0 && traction[1] == -7.0 && tangent[0] == -7.0 && state_new[0] == -7.0 && psi == -7.0,
        "bad sf_N: outputs were touched");

  /* bad K_T, without a detail buffer */
  paper_props(props);
  props[8] = -1.0;
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s, traction, tangent, state_new, &psi, NULL, 0);
  CHECK(status == INTERPHASE_STATUS_BAD_K_T, "bad K_T: status %d", status);

  /* wrong nprops and ntens */
  paper_props(props);
  status = interphase_update(props, 8, 2, state, s, traction, tangent, state_new, &psi, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_NPROPS, "nprops = 8: status %d", status);
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 4, state, s, traction, tangent, state_new, &psi, detail,
                             sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_NTENS && strstr(detail, "ntens = 4") != NULL, "ntens = 4: status %d, \"%s\"",
        status, detail);

  /* NaN separation */
  const double s_nan[2] = {NAN, 0.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s_nan, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_NONFINITE_SEPARATION, "NaN separation: status %d", status);
  CHECK(traction[0] == -7.0 && psi == -7.0, "NaN separation: outputs were touched");

  /* bad old state: D > 1 */
  const double bad_state[INTERPHASE_NSTATE] = {1.5, 0.0, 0.0, 0.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, bad_state, s, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_STATE && strstr(detail, "STATEV(1)") != NULL, "D = 1.5: status %d, \"%s\"",
        status, detail);

  /* 3-D call works and the shear components are independent of the detail buffer */
  double t3[3], k3[9];
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 3, state, (const double[3]){-0.001, 0.0003, 0.0002},
                             t3, k3, state_new, &psi, NULL, 0);
  CHECK(status == INTERPHASE_STATUS_OK && close_to(t3[0], -0.001 * K_N, 0, 1e-14) && close_to(t3[1], 0.0003 * K_T, 0, 1e-14) &&
            close_to(t3[2], 0.0002 * K_T, 0, 1e-14) && k3[4] == K_T && k3[8] == K_T && k3[1] == 0.0,
        "3-D elastic call: status %d, traction (%g, %g, %g)", status, t3[0], t3[1], t3[2]);

  /* status messages: truncation and full length, like snprintf */
  char small[5];
  size_t n = interphase_status_message(INTERPHASE_STATUS_OK, small, sizeof small);
  CHECK(n == strlen("success") && strcmp(small, "succ") == 0, "truncated message \"%s\", length %zu", small, n);
  n = interphase_status_message(INTERPHASE_STATUS_NONFINITE_SEPARATION, NULL, 0);
  CHECK(n == strlen("separation is not finite (NaN or Inf)"), "length of message 20: %zu", n);
  interphase_status_message(9999, msg, sizeof msg);
  CHECK(strcmp(msg, "unknown status code") == 0, "status 9999: \"%s\"", msg);
  /* every status the header names has a message of its own */
  const int codes[] = {INTERPHASE_STATUS_BAD_NPROPS, INTERPHASE_STATUS_BAD_MODEL, INTERPHASE_STATUS_BAD_DAMAGE_LAW,
                       INTERPHASE_STATUS_BAD_MU, INTERPHASE_STATUS_BAD_S0_N, INTERPHASE_STATUS_BAD_SF_N,
                       INTERPHASE_STATUS_BAD_S0_T, INTERPHASE_STATUS_BAD_SF_T, INTERPHASE_STATUS_BAD_K_N,
                       INTERPHASE_STATUS_BAD_K_T, INTERPHASE_STATUS_BAD_NTENS, INTERPHASE_STATUS_MODEL_UNAVAILABLE,
                       INTERPHASE_STATUS_NONFINITE_SEPARATION, INTERPHASE_STATUS_BAD_STATE,
                       INTERPHASE_STATUS_BAD_COEFFICIENTS};
  for (size_t i = 0; i < sizeof codes / sizeof codes[0]; ++i) {
    interphase_status_message(codes[i], msg, sizeof msg);
    CHECK(strcmp(msg, "unknown status code") != 0, "status %d has no message", codes[i]);
  }
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s <tests/driver/reference/mixed.csv>\n", argv[0]);
    return 2;
  }
  test_mixed_history(argv[1]);
  test_failures();
  printf("%d checks, %d failed\n", checks, failures);
  return failures == 0 ? 0 : 1;
}
