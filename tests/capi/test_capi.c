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
 * 3a. The header's promises to a host: the dissipated energy accumulated as it says equals
 *    interphase_run's bit for bit (the driver's W_dis to the reference's tolerance); an update in place (state_new == state_old) and a restart from
 *    the state written as text give the same numbers; a failed update in place keeps the state.
 * 4. Failures: a bad PROPS value, a bad ntens and a NaN separation return the right status and
 *    message and leave the outputs untouched; interphase_status_message truncates like snprintf;
 *    every status code of the header has a message of its own.
 *
 *   test_capi --load <tables/paper.dat> <tables/paper-resolution.dat>
 *
 * 5. The loaders (interphase_load_table, interphase_load_rcurve), in a fresh process: before a
 *    load the custom table / tabulated R-curve is "not loaded"; a missing file, a malformed file
 *    (written into the working directory), a NULL and an empty path fail with the right status
 *    and a message naming the file (and the line); paper.dat loaded as the custom table gives the
 *    built-in table's update (the library's default is compiled from that same file); a failed
 *    load keeps the table loaded before; paper-resolution.dat then gives a different response.
 *    A tabulated constant R-curve gives the constant R-curve's update.
 *
 * 6. interphase_run_history: the mixed history replayed as interphase-point replays it, the
 *    reference CSV's rows; a shear test under an imposed precompression (mixed
 *    control); the statuses of a traction beyond the peak, a bad history, short output arrays.
 *
 * Exits 0 when every check passes, 1 otherwise, printing each failed check.
 */
/* (feenableexcept: a GNU extension of <fenv.h>, to run one call with the overflow trap on) */
#define _GNU_SOURCE
#include <fenv.h>
#include <math.h>
#include <stdint.h>
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

/* The most rows of a driver CSV the tests read (the mixed history has 1201). */
#define CSV_MAX_ROWS 4096

/* One row of the driver's CSV (t,s_T,s_N,Sigma_T,Sigma_N,D,slip,state,psi,W_dis). */
struct csv_row {
  double t, s_t, s_n, sig_t, sig_n, d, slip, psi, w_dis;
  int regime; /* the state column's REGIME_* code */
};

/* Read up to max rows of a driver CSV after its header (which must start with the driver's
 * columns); returns the number of rows read, or 0 (with a failed check) when the file cannot be
 * opened or its header is not the driver's. */
static size_t read_driver_csv(const char *csv_path, struct csv_row *rows, size_t max) {
  FILE *f = fopen(csv_path, "r");
  CHECK(f != NULL, "cannot open %s", csv_path);
  if (f == NULL) return 0;
  char header[256];
  const int header_ok =
      fgets(header, sizeof header, f) != NULL && strncmp(header, "t,s_T,s_N,Sigma_T,Sigma_N,D,slip,state,psi", 42) == 0;
  CHECK(header_ok, "unexpected CSV header in %s", csv_path);
  size_t n = 0;
  char regime[32];
  while (header_ok && n < max) {
    struct csv_row *r = &rows[n];
    if (fscanf(f, " %lf,%lf,%lf,%lf,%lf,%lf,%lf,%31[^,],%lf,%lf", &r->t, &r->s_t, &r->s_n, &r->sig_t, &r->sig_n, &r->d,
               &r->slip, regime, &r->psi, &r->w_dis) != 10)
      break;
    r->regime = regime_code(regime);
    ++n;
  }
  fclose(f);
  return n;
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
  static struct csv_row csv[CSV_MAX_ROWS];
  const size_t nrows = read_driver_csv(csv_path, csv, sizeof csv / sizeof csv[0]);
  CHECK(nrows > 1000, "only %zu rows read from %s", nrows, csv_path);

  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  double state[INTERPHASE_NSTATE] = {0.0, 0.0, 0.0, 0.0};
  int rows = 0, elastic_rows = 0, coulomb_rows = 0, tangent_checked = 0;
  for (size_t row = 0; row < nrows; ++row) {
    const double t = csv[row].t, s_t = csv[row].s_t, s_n = csv[row].s_n, sig_t = csv[row].sig_t,
                 sig_n = csv[row].sig_n, d = csv[row].d, slip = csv[row].slip, psi_ref = csv[row].psi;
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
    CHECK((int)state_new[3] == csv[row].regime, "row %d: regime %g, reference %d", rows, state_new[3], csv[row].regime);

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
  CHECK(elastic_rows > 10, "only %d intact rows", elastic_rows);
  CHECK(coulomb_rows > 100, "only %d rows slipping at D = 1", coulomb_rows);
  CHECK(tangent_checked == 3, "tangent checked on %d rows", tangent_checked);
  printf("mixed history: %d rows, %d intact, %d slipping at D = 1\n", rows, elastic_rows, coulomb_rows);
}

/* The header's promises to a host that keeps its own energies and restarts: along the mixed
 * history, the dissipated energy accumulated as the header says (W_old + 1/2 sum (t_old + t)(s -
 * s_old) - (psi - psi_old), s formed as s_old + (s - s_old)) equals interphase_run's bit for bit
 * and the driver's W_dis to the reference's tolerance; the state updated in place (state_new ==
 * state_old) gives the same numbers, and a failed update in place leaves it as it was; the state
 * written with "%.17g" and read back halfway continues bit for bit. */
static void test_energy_in_place_and_restart(const char *csv_path) {
  static struct csv_row csv[CSV_MAX_ROWS];
  static double path_s[2 * CSV_MAX_ROWS], path_t[2 * CSV_MAX_ROWS], path_state[INTERPHASE_NSTATE * CSV_MAX_ROWS],
      path_psi[CSV_MAX_ROWS], path_w[CSV_MAX_ROWS];
  const size_t nrows = read_driver_csv(csv_path, csv, sizeof csv / sizeof csv[0]);
  CHECK(nrows > 1000, "only %zu rows read from %s", nrows, csv_path);
  if (nrows < 2) return;
  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  double state[INTERPHASE_NSTATE] = {0.0}, s_old[2], t_old[2], psi_old, w;
  double tangent[4];
  char detail[257] = "";
  /* row 0: the driver's start (its preload is elastic: one step from the virgin point) */
  s_old[0] = csv[0].s_n;
  s_old[1] = csv[0].s_t;
  int status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s_old, t_old, tangent, state, &psi_old,
                                 detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK, "row 0: status %d: %s", status, detail);
  w = csv[0].w_dis;
  /* the same path through interphase_run, from the same start */
  for (size_t row = 0; row < nrows; ++row) {
    path_s[2 * row] = csv[row].s_n;
    path_s[2 * row + 1] = csv[row].s_t;
  }
  memcpy(path_t, t_old, sizeof t_old);
  memcpy(path_state, state, sizeof state);
  path_psi[0] = psi_old;
  path_w[0] = w;
  size_t done = 0;
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, nrows, path_s, NULL, path_t, NULL, path_state, path_psi,
                          path_w, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == nrows, "interphase_run: status %d, %zu rows: %s", status, done, detail);
  int w_differs = 0, restarted = 0;
  for (size_t row = 1; row < nrows && status == INTERPHASE_STATUS_OK; ++row) {
    if (row == nrows / 2) { /* restart: the state through text */
      char text[INTERPHASE_NSTATE][32];
      for (int k = 0; k < INTERPHASE_NSTATE; ++k) snprintf(text[k], sizeof text[k], "%.17g", state[k]);
      for (int k = 0; k < INTERPHASE_NSTATE; ++k) state[k] = strtod(text[k], NULL);
      restarted = 1;
    }
    const double s_row[2] = {csv[row].s_n, csv[row].s_t};
    const double s[2] = {s_old[0] + (s_row[0] - s_old[0]), s_old[1] + (s_row[1] - s_old[1])};
    double t[2], psi, separate[INTERPHASE_NSTATE], t_separate[2], psi_separate;
    status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s, t_separate, tangent, separate,
                               &psi_separate, detail, sizeof detail);
    CHECK(status == INTERPHASE_STATUS_OK, "row %zu: status %d: %s", row, status, detail);
    status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s, t, tangent, state, &psi, detail,
                               sizeof detail);
    CHECK(status == INTERPHASE_STATUS_OK, "row %zu (in place): status %d: %s", row, status, detail);
    if (status != INTERPHASE_STATUS_OK) break;
    CHECK(memcmp(state, separate, sizeof state) == 0 && memcmp(t, t_separate, sizeof t) == 0 && psi == psi_separate,
          "row %zu: the update in place differs from the one into another array", row);
    w = w + 0.5 * ((t_old[0] + t[0]) * (s[0] - s_old[0]) + (t_old[1] + t[1]) * (s[1] - s_old[1])) - (psi - psi_old);
    if (done == nrows && !(w == path_w[row] && psi == path_psi[row] &&
                           memcmp(state, &path_state[INTERPHASE_NSTATE * row], sizeof state) == 0) &&
        w_differs++ < 3)
      CHECK(0, "row %zu: W = %.17g, psi = %.17g, D = %.17g; interphase_run: %.17g, %.17g, %.17g", row, w, psi, state[0],
            path_w[row], path_psi[row], path_state[INTERPHASE_NSTATE * row]);
    CHECK(close_to(w, csv[row].w_dis, 1e-12, 1e-9), "row %zu: W = %.17g, the driver's W_dis %.17g", row, w,
          csv[row].w_dis);
    memcpy(s_old, s, sizeof s_old);
    memcpy(t_old, t, sizeof t_old);
    psi_old = psi;
  }
  CHECK(w_differs == 0, "W, psi or the state differ from interphase_run's on %d rows", w_differs);
  CHECK(restarted, "no restart made");
  /* a failed update in place leaves the state as it was */
  double kept[INTERPHASE_NSTATE], t[2], psi;
  memcpy(kept, state, sizeof kept);
  const double bad[2] = {NAN, 0.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, bad, t, tangent, state, &psi, detail,
                             sizeof detail);
  CHECK(status == INTERPHASE_STATUS_NONFINITE_SEPARATION, "NaN separation in place: status %d", status);
  CHECK(memcmp(state, kept, sizeof kept) == 0, "a failed update in place changed the state");
  printf("energies: %zu rows, W as the header says = interphase_run's; in place and restarted\n", nrows);
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

  /* a material with viscous regularisation through interphase_update: refused with
     BAD_TIME_INCREMENT before its state is read. The caller's state holds INTERPHASE_NSTATE
     doubles, as the header says; the double after them (here an inadmissible "STATEV(5)") must
     not be read: a read past the array reported it as BAD_STATE naming STATEV(5). */
  {
    double vprops[INTERPHASE_NPROPS_SIMPLIFIED + 3];
    paper_props(vprops);
    vprops[9] = 0.0;   /* growth slip: default */
    vprops[10] = 0.0;  /* contact band: none */
    vprops[11] = 1.0;  /* viscosity eta = 1 s */
    const double block[INTERPHASE_NSTATE + 1] = {0.0, 0.0, 0.0, 0.0, -3.0};
    detail[0] = '\0';
    status = interphase_update(vprops, INTERPHASE_NPROPS_SIMPLIFIED + 3, 2, block, s, traction, tangent, state_new, &psi,
                               detail, sizeof detail);
    CHECK(status == INTERPHASE_STATUS_BAD_TIME_INCREMENT && strstr(detail, "interphase_update_dt") != NULL,
          "viscous material through interphase_update: status %d, \"%s\"", status, detail);
    CHECK(traction[0] == -7.0 && psi == -7.0, "viscous material through interphase_update: outputs were touched");
  }

  /* NaN separation */
  const double s_nan[2] = {NAN, 0.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s_nan, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_NONFINITE_SEPARATION && strstr(detail, "separation s_N, s_T (mm)") != NULL &&
            strstr(detail, ": not finite") != NULL,
        "NaN separation: status %d, \"%s\"", status, detail);
  CHECK(traction[0] == -7.0 && psi == -7.0, "NaN separation: outputs were touched");

  /* a finite separation beyond the admissible range, and one at its edge */
  const double s_far[2] = {0.0, -2.0 * INTERPHASE_SEPARATION_MAX}, s_edge[2] = {INTERPHASE_SEPARATION_MAX, 0.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s_far, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE && strstr(detail, "-2.0000E+20") != NULL &&
            strstr(detail, "separation s_N, s_T (mm)") != NULL && strstr(detail, ": beyond |s_i| <= ") != NULL,
        "separation -2e20 mm: status %d, \"%s\"", status, detail);
  CHECK(traction[0] == -7.0 && psi == -7.0, "separation -2e20 mm: outputs were touched");
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s_edge, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && isfinite(psi) && isfinite(traction[0]) && state_new[0] == 1.0,
        "separation 1e20 mm: status %d, psi %g, D %g", status, psi, state_new[0]);
  traction[0] = -7.0;
  psi = -7.0;

  /* bad old state: D > 1 */
  const double bad_state[INTERPHASE_NSTATE] = {1.5, 0.0, 0.0, 0.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, bad_state, s, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_STATE && strstr(detail, "STATEV(1)") != NULL, "D = 1.5: status %d, \"%s\"",
        status, detail);

  /* bad old state: a slip that is not finite; the message says what the slot must hold */
  const double nan_slip[INTERPHASE_NSTATE] = {0.5, NAN, 0.0, 2.0};
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, nan_slip, s, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_STATE && strstr(detail, "STATEV(2:3) slip = ") != NULL &&
            strstr(detail, "NaN") != NULL && strstr(detail, "must be finite with |lambda_i| <= 1.0E+30 mm") != NULL,
        "slip NaN: status %d, \"%s\"", status, detail);

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
  CHECK(strcmp(msg, "unknown status code 9999") == 0, "status 9999: \"%s\"", msg);
  /* every status the header names has a message of its own (ctest capi_status_codes_match checks
     that the header names every code of src/interphase_status.f90, with the same values) */
  const int codes[] = {
      INTERPHASE_STATUS_BAD_NPROPS, INTERPHASE_STATUS_BAD_MODEL, INTERPHASE_STATUS_BAD_DAMAGE_LAW,
      INTERPHASE_STATUS_BAD_MU, INTERPHASE_STATUS_BAD_S0_N, INTERPHASE_STATUS_BAD_SF_N, INTERPHASE_STATUS_BAD_S0_T,
      INTERPHASE_STATUS_BAD_SF_T, INTERPHASE_STATUS_BAD_K_N, INTERPHASE_STATUS_BAD_K_T, INTERPHASE_STATUS_BAD_NTENS,
      INTERPHASE_STATUS_BAD_NSTATV, INTERPHASE_STATUS_MODEL_UNAVAILABLE, INTERPHASE_STATUS_BAD_TABLE_SELECTOR,
      INTERPHASE_STATUS_BAD_D0, INTERPHASE_STATUS_BAD_RCURVE, INTERPHASE_STATUS_BAD_GC_I, INTERPHASE_STATUS_BAD_GC_II,
      INTERPHASE_STATUS_NONFINITE_SEPARATION, INTERPHASE_STATUS_BAD_STATE, INTERPHASE_STATUS_BAD_COEFFICIENTS,
      INTERPHASE_STATUS_STAGGER_NOT_CONVERGED, INTERPHASE_STATUS_RCURVE_NOT_LOADED,
      INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE, INTERPHASE_STATUS_BAD_HOST_INPUT, INTERPHASE_STATUS_BAD_OPTION,
      INTERPHASE_STATUS_SPLINE_TOO_FEW_POINTS, INTERPHASE_STATUS_SPLINE_BAD_SHAPE, INTERPHASE_STATUS_SPLINE_BAD_METHOD,
      INTERPHASE_STATUS_SPLINE_NONFINITE_DATA, INTERPHASE_STATUS_SPLINE_BAD_KNOTS,
      INTERPHASE_STATUS_SPLINE_SOLVER_FAILED, INTERPHASE_STATUS_SPLINE_NOT_BUILT,
      INTERPHASE_STATUS_SPLINE_OUT_OF_RANGE, INTERPHASE_STATUS_SPLINE_NONFINITE_ARGUMENT,
      INTERPHASE_STATUS_TABLE_UNREADABLE, INTERPHASE_STATUS_TABLE_BAD_HEADER, INTERPHASE_STATUS_TABLE_MISSING_COLUMN,
      INTERPHASE_STATUS_TABLE_MISSING_KEY, INTERPHASE_STATUS_TABLE_BAD_ROW, INTERPHASE_STATUS_TABLE_NONFINITE,
      INTERPHASE_STATUS_TABLE_NOT_INCREASING, INTERPHASE_STATUS_TABLE_BAD_RANGE, INTERPHASE_STATUS_TABLE_IDENTITY,
      INTERPHASE_STATUS_TABLE_NOT_LOADED, INTERPHASE_STATUS_RCURVE_UNREADABLE, INTERPHASE_STATUS_RCURVE_MALFORMED,
      INTERPHASE_STATUS_RCURVE_NEGATIVE, INTERPHASE_STATUS_RCURVE_BAD_RANGE, INTERPHASE_STATUS_RCURVE_OUT_OF_RANGE,
      INTERPHASE_STATUS_NULL_ARGUMENT, INTERPHASE_STATUS_RCURVE_BAD_TOUGHNESS};
  for (size_t i = 0; i < sizeof codes / sizeof codes[0]; ++i) {
    interphase_status_message(codes[i], msg, sizeof msg);
    CHECK(strncmp(msg, "unknown status code", 19) != 0, "status %d has no message", codes[i]);
    for (size_t j = 0; j < i; ++j) CHECK(codes[i] != codes[j], "status %d named twice", codes[i]);
  }
}

/* ---- 5. the loaders ------------------------------------------------------------------------ */

/* Micromechanical model (docs/abaqus.md): PROPS[0] = 2, damage law 1, mu, s0/sf, PROPS[7] = table. */
#define NPROPS_MICRO 8
static void micro_props(double props[NPROPS_MICRO], double table) {
  const double p[NPROPS_MICRO] = {2.0, 1.0, MU, 0.00044, 0.04, 0.00072, 0.06, table};
  memcpy(props, p, sizeof p);
}

/* Simplified model with the fracture-mechanics law (PROPS[1] = 2): PROPS[9..12] = D0, R-curve,
   G_cI, G_cII. */
#define NPROPS_FRACTURE (INTERPHASE_NPROPS_SIMPLIFIED + 4)
static void fracture_props(double props[NPROPS_FRACTURE], double rcurve, double gc_i, double gc_ii) {
  paper_props(props);
  props[1] = 2.0;
  props[9] = 0.05;
  props[10] = rcurve;
  props[11] = gc_i;
  props[12] = gc_ii;
}

static void write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  CHECK(f != NULL, "cannot write %s", path);
  if (f == NULL) return;
  fputs(text, f);
  fclose(f);
}

/* One point of a 2-D history: separation (s_N, s_T) at step i of n, opening then shearing. */
static void history_point(int i, int n, double s[2]) {
  const double u = (double)i / (double)n;
  s[0] = 0.02 * (u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u) - 0.001 * u; /* open, close, press */
  s[1] = 0.03 * u;                                               /* shear */
}

/* Runs the history with two PROPS sets side by side; returns the largest relative difference of
   traction, tangent, state and stored energy, or -1 if an update failed. */
static double compare_histories(const double *props_a, const double *props_b, int nprops, const char *what,
                                double *d_final) {
  double state_a[INTERPHASE_NSTATE] = {0.0}, state_b[INTERPHASE_NSTATE] = {0.0};
  double largest = 0.0;
  const int n = 200;
  for (int i = 1; i <= n; ++i) {
    double s[2], ta[2], tb[2], ka[4], kb[4], na[INTERPHASE_NSTATE], nb[INTERPHASE_NSTATE], pa, pb;
    char detail[257] = "";
    history_point(i, n, s);
    int status = interphase_update(props_a, nprops, 2, state_a, s, ta, ka, na, &pa, detail, sizeof detail);
    CHECK(status == INTERPHASE_STATUS_OK, "%s, step %d: status %d: %s", what, i, status, detail);
    if (status != INTERPHASE_STATUS_OK) return -1.0;
    status = interphase_update(props_b, nprops, 2, state_b, s, tb, kb, nb, &pb, detail, sizeof detail);
    CHECK(status == INTERPHASE_STATUS_OK, "%s, step %d (reference): status %d: %s", what, i, status, detail);
    if (status != INTERPHASE_STATUS_OK) return -1.0;
    double scale_t = fabs(tb[0]) + fabs(tb[1]) + 1e-300, scale_k = fabs(kb[0]) + fabs(kb[3]) + 1e-300;
    for (int k = 0; k < 2; ++k) largest = fmax(largest, fabs(ta[k] - tb[k]) / scale_t);
    for (int k = 0; k < 4; ++k) largest = fmax(largest, fabs(ka[k] - kb[k]) / scale_k);
    for (int k = 0; k < INTERPHASE_NSTATE; ++k) largest = fmax(largest, fabs(na[k] - nb[k]));
    largest = fmax(largest, fabs(pa - pb) / (fabs(pb) + 1e-300));
    memcpy(state_a, na, sizeof state_a);
    memcpy(state_b, nb, sizeof state_b);
  }
  *d_final = state_a[0];
  return largest;
}

/* A load that must fail with `expected`, its detail naming `fragment`; NULL detail must not crash. */
static void expect_load_failure(int (*load)(const char *, char *, size_t), const char *path, int expected,
                                const char *fragment) {
  char detail[257] = "";
  int status = load(path, detail, sizeof detail);
  CHECK(status == expected, "load(\"%s\"): status %d, expected %d (%s)", path ? path : "NULL", status, expected, detail);
  CHECK(strstr(detail, fragment) != NULL, "load(\"%s\"): detail \"%s\" does not name \"%s\"", path ? path : "NULL",
        detail, fragment);
  CHECK(load(path, NULL, 0) == expected, "load(\"%s\") without a detail buffer", path ? path : "NULL");
  printf("  load(%s): status %d: %s\n", path ? path : "NULL", status, detail);
}

static void test_load_table(const char *paper, const char *coarse) {
  double custom[NPROPS_MICRO], builtin[NPROPS_MICRO], traction[2] = {-7.0, -7.0}, tangent[4] = {-7.0}, psi = -7.0;
  double state_new[INTERPHASE_NSTATE] = {-7.0}, d_final = 0.0;
  const double state[INTERPHASE_NSTATE] = {0.0}, s[2] = {0.001, 0.0005};
  char detail[257] = "", msg[257];
  micro_props(custom, 1.0);
  micro_props(builtin, 0.0);

  /* before any load: "custom RVE table selected but none loaded", outputs untouched */
  int status = interphase_update(custom, NPROPS_MICRO, 2, state, s, traction, tangent, state_new, &psi, detail,
                                 sizeof detail);
  interphase_status_message(status, msg, sizeof msg);
  CHECK(status == INTERPHASE_STATUS_TABLE_NOT_LOADED && strcmp(msg, "custom RVE table selected but none loaded") == 0,
        "no table loaded: status %d \"%s\"", status, msg);
  CHECK(strstr(detail, "PROPS(8) = 1 (props[7] in C) selects the custom RVE table") != NULL &&
            strstr(detail, "call interphase_load_table(path, ...)") != NULL,
        "no table loaded: detail \"%s\"", detail);
  CHECK(traction[0] == -7.0 && tangent[0] == -7.0 && state_new[0] == -7.0 && psi == -7.0,
        "no table loaded: outputs were touched");

  /* a missing file, a malformed file, a NULL and an empty path: clear errors, nothing loaded */
  expect_load_failure(interphase_load_table, "no-such-dir/missing-table.dat", INTERPHASE_STATUS_TABLE_UNREADABLE,
                      "no-such-dir/missing-table.dat");
  char columns[400] = "# columns:";
  const char *names[] = {"a",    "D",     "C_TT",  "C_TN",  "C_NT",  "C_NN", "Dbar_TT", "Dbar_TN",
                         "Dbar_NT", "Dbar_NN", "Cc_TT", "Cc_TN", "Cc_NT", "Cc_NN", "Tc_T", "Tc_N",
                         "Sc_T", "Sc_N",  "Cf_T",  "Cf_N",  "Tf",    "Sf",   "ufbar"};
  for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
    strcat(columns, " ");
    strcat(columns, names[i]);
  }
  char text[1024];
  snprintf(text, sizeof text, "# b = 25\n# h = 5\n%s\n0 0 1000\n", columns);
  write_file("bad_row_table.dat", text); /* line 4 holds 3 numbers for 23 columns */
  expect_load_failure(interphase_load_table, "bad_row_table.dat", INTERPHASE_STATUS_TABLE_BAD_ROW,
                      "bad_row_table.dat:4: 3 numbers");
  write_file("bad_header_table.dat", "# b = 25\n# h = minus one\n");
  expect_load_failure(interphase_load_table, "bad_header_table.dat", INTERPHASE_STATUS_TABLE_BAD_HEADER,
                      "bad_header_table.dat:2:");
  expect_load_failure(interphase_load_table, NULL, INTERPHASE_STATUS_TABLE_UNREADABLE, "path is NULL");
  expect_load_failure(interphase_load_table, "", INTERPHASE_STATUS_TABLE_UNREADABLE, "RVE table path is empty");
  status = interphase_update(custom, NPROPS_MICRO, 2, state, s, traction, tangent, state_new, &psi, NULL, 0);
  CHECK(status == INTERPHASE_STATUS_TABLE_NOT_LOADED, "after failed loads: status %d", status);

  /* paper.dat as the custom table: the built-in table's response (compiled from the same file) */
  status = interphase_load_table(paper, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK, "load %s: status %d: %s", paper, status, detail);
  double diff = compare_histories(custom, builtin, NPROPS_MICRO, "custom paper.dat vs built-in", &d_final);
  CHECK(diff >= 0.0 && diff <= 1e-12, "custom paper.dat vs built-in: largest relative difference %g", diff);
  CHECK(d_final > 0.5, "the history damages the point only to D = %g", d_final);
  printf("custom table %s: D = %.4f at the end, largest difference from the built-in table %.3g\n", paper, d_final,
         diff);

  /* a failed load keeps the table loaded before */
  expect_load_failure(interphase_load_table, "bad_row_table.dat", INTERPHASE_STATUS_TABLE_BAD_ROW, "bad_row_table.dat");
  diff = compare_histories(custom, builtin, NPROPS_MICRO, "after a failed load", &d_final);
  CHECK(diff >= 0.0 && diff <= 1e-12, "after a failed load: largest relative difference %g", diff);

  /* another table replaces it: the coarse table's response differs */
  status = interphase_load_table(coarse, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK, "load %s: status %d: %s", coarse, status, detail);
  diff = compare_histories(custom, builtin, NPROPS_MICRO, "custom coarse table vs built-in", &d_final);
  CHECK(diff > 1e-3, "custom coarse table vs built-in: largest relative difference only %g", diff);
  printf("custom table %s: largest difference from the built-in table %.3g\n", coarse, diff);
}

static void test_load_rcurve(void) {
  double tabulated[NPROPS_FRACTURE], constant[NPROPS_FRACTURE], traction[2], tangent[4], psi, d_final = 0.0;
  double state_new[INTERPHASE_NSTATE];
  const double state[INTERPHASE_NSTATE] = {0.0}, s[2] = {0.001, 0.0005};
  char detail[257] = "";
  const double g_i = 0.005, g_ii = 0.0085; /* N/mm */
  fracture_props(tabulated, 3.0, 0.0, 0.0);
  fracture_props(constant, 1.0, g_i, g_ii);

  int status = interphase_update(tabulated, NPROPS_FRACTURE, 2, state, s, traction, tangent, state_new, &psi, NULL, 0);
  CHECK(status == INTERPHASE_STATUS_RCURVE_NOT_LOADED, "no R-curve loaded: status %d", status);
  char why[300];
  interphase_update(tabulated, NPROPS_FRACTURE, 2, state, s, traction, tangent, state_new, &psi, why, sizeof why);
  CHECK(strstr(why, "PROPS(11) = 3 (props[10] in C) selects the tabulated R-curve") != NULL,
        "no R-curve loaded: detail \"%s\"", why);

  expect_load_failure(interphase_load_rcurve, "no-such-dir/missing-rcurve.txt", INTERPHASE_STATUS_RCURVE_UNREADABLE,
                      "no-such-dir/missing-rcurve.txt");
  write_file("bad_rcurve.txt", "# D G_cI G_cII\n0.0 0.005\n1.0 0.005 0.0085\n");
  expect_load_failure(interphase_load_rcurve, "bad_rcurve.txt", INTERPHASE_STATUS_RCURVE_MALFORMED,
                      "bad_rcurve.txt:2: expected three finite numbers");
  write_file("negative_rcurve.txt", "0.0 0.005 0.0085\n1.0 -0.005 0.0085\n");
  expect_load_failure(interphase_load_rcurve, "negative_rcurve.txt", INTERPHASE_STATUS_RCURVE_NEGATIVE,
                      "negative_rcurve.txt:2:");
  expect_load_failure(interphase_load_rcurve, NULL, INTERPHASE_STATUS_RCURVE_UNREADABLE, "path is NULL");
  /* a toughness outside [1e-20, 1e20] N/mm: a status of its own, whose text says so (it was 63, "D
     values not strictly increasing") */
  write_file("huge_gc_rcurve.txt", "0 1e21 0.0085\n1 0.005 0.0085\n");
  expect_load_failure(interphase_load_rcurve, "huge_gc_rcurve.txt", INTERPHASE_STATUS_RCURVE_BAD_TOUGHNESS,
                      "huge_gc_rcurve.txt:1: G_cI = 1e21 lies outside [1e-20, 1e20] N/mm");
  write_file("tiny_gc_rcurve.txt", "0 0.005 1e-21\n1 0.005 0.0085\n");
  expect_load_failure(interphase_load_rcurve, "tiny_gc_rcurve.txt", INTERPHASE_STATUS_RCURVE_BAD_TOUGHNESS,
                      "tiny_gc_rcurve.txt:1: G_cII = 1e-21 lies outside [1e-20, 1e20] N/mm");
  {
    char reason[128];
    interphase_status_message(INTERPHASE_STATUS_RCURVE_BAD_TOUGHNESS, reason, sizeof reason);
    CHECK(strcmp(reason, "R-curve toughness outside [1e-20, 1e20] N/mm") == 0, "status 65: \"%s\"", reason);
  }

  /* a constant tabulated R-curve: the constant R-curve's response */
  char text[256];
  snprintf(text, sizeof text, "# D G_cI G_cII (N/mm)\n0.0 %.17g %.17g\n0.5 %.17g %.17g\n1.0 %.17g %.17g\n", g_i, g_ii,
           g_i, g_ii, g_i, g_ii);
  write_file("constant_rcurve.txt", text);
  status = interphase_load_rcurve("constant_rcurve.txt", detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK, "load constant_rcurve.txt: status %d: %s", status, detail);
  double diff = compare_histories(tabulated, constant, NPROPS_FRACTURE, "tabulated vs constant R-curve", &d_final);
  CHECK(diff >= 0.0 && diff <= 1e-12, "tabulated vs constant R-curve: largest relative difference %g", diff);
  CHECK(d_final > 0.5, "the history damages the point only to D = %g", d_final);
  printf("tabulated R-curve: D = %.4f at the end, largest difference from the constant R-curve %.3g\n", d_final, diff);

  /* an R-curve that covers D0 = 0.05 but not the damage reached: status 64 once the crack grows
     beyond D = 0.3, the outputs untouched, the detail naming the file, its range and the D */
  write_file("short_rcurve.txt", "0.0 0.005 0.0085\n0.1 0.005 0.0085\n0.2 0.005 0.0085\n0.3 0.005 0.0085\n");
  status = interphase_load_rcurve("short_rcurve.txt", detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK, "load short_rcurve.txt: status %d: %s", status, detail);
  double state_old[INTERPHASE_NSTATE] = {0.0}, kept[INTERPHASE_NSTATE];
  int step = 0;
  status = INTERPHASE_STATUS_OK;
  for (step = 1; step <= 1000 && status == INTERPHASE_STATUS_OK; ++step) {
    const double opening[2] = {0.00005 * step, 0.0};
    memcpy(kept, state_new, sizeof kept);
    status = interphase_update(tabulated, NPROPS_FRACTURE, 2, state_old, opening, traction, tangent, state_new, &psi,
                               detail, sizeof detail);
    if (status == INTERPHASE_STATUS_OK) memcpy(state_old, state_new, sizeof state_old);
  }
  CHECK(status == INTERPHASE_STATUS_RCURVE_OUT_OF_RANGE, "short R-curve: status %d (expected 64): %s", status, detail);
  CHECK(memcmp(kept, state_new, sizeof kept) == 0, "short R-curve: state_new touched on failure");
  CHECK(strstr(detail, "short_rcurve.txt covers D from 0.00000 to 0.300000") != NULL &&
            strstr(detail, "grows beyond it from D = ") != NULL,
        "short R-curve: detail \"%s\"", detail);
  CHECK(state_old[0] <= 0.3 && step > 2, "short R-curve: last D = %g after %d updates", state_old[0], step - 1);
  /* a virgin point (D = 0 in its state) opened at once beyond the snap: the crack grows from D0,
     which the detail names, not from the state's 0 */
  const double virgin[INTERPHASE_NSTATE] = {0.0}, open_at_once[2] = {0.0046, 0.0};
  status = interphase_update(tabulated, NPROPS_FRACTURE, 2, virgin, open_at_once, traction, tangent, state_new, &psi,
                             detail, sizeof detail);
  const char *from = strstr(detail, "grows beyond it from D = ");
  double d_from = from == NULL ? -1.0 : strtod(from + strlen("grows beyond it from D = "), NULL);
  CHECK(status == INTERPHASE_STATUS_RCURVE_OUT_OF_RANGE && d_from == 0.05,
        "short R-curve, virgin point: status %d, the crack grows from D = %g (D0 = 0.05): %s", status, d_from, detail);
}

/* interphase_run: the mixed history's rows (the driver's CSV) along one path in one call, equal
 * bit for bit to interphase_update_dt called step by step as the UMAT is (the update at
 * s[i-1] + (s[i] - s[i-1]), SPD accumulated), close to the CSV; then its failures. */
#define RUN_MAX_ROWS CSV_MAX_ROWS
static void test_run(const char *csv_path) {
  static double sep[RUN_MAX_ROWS * 2], tim[RUN_MAX_ROWS], tra[RUN_MAX_ROWS * 2], tan_[RUN_MAX_ROWS * 4],
      sta[RUN_MAX_ROWS * INTERPHASE_NSTATE], psi[RUN_MAX_ROWS], wd[RUN_MAX_ROWS], ref[RUN_MAX_ROWS][5];
  static struct csv_row csv[RUN_MAX_ROWS];
  const size_t n = read_driver_csv(csv_path, csv, RUN_MAX_ROWS);
  for (size_t i = 0; i < n; ++i) {
    tim[i] = csv[i].t;
    sep[2 * i] = csv[i].s_n;
    sep[2 * i + 1] = csv[i].s_t;
    ref[i][0] = csv[i].sig_n, ref[i][1] = csv[i].sig_t, ref[i][2] = csv[i].d, ref[i][3] = csv[i].psi;
    ref[i][4] = csv[i].w_dis;
  }
  if (n > 0) { /* the start: the CSV's first row */
    tra[0] = csv[0].sig_n, tra[1] = csv[0].sig_t;
    sta[0] = csv[0].d, sta[1] = csv[0].slip, sta[2] = 0.0, sta[3] = csv[0].regime;
    psi[0] = csv[0].psi, wd[0] = csv[0].w_dis;
  }
  CHECK(n > 1000, "only %zu rows read from %s", n, csv_path);
  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  size_t done = 0;
  char detail[257] = "";
  int status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, n, sep, tim, tra, tan_, sta, psi, wd, &done,
                              detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == n, "interphase_run: status %d, %zu of %zu rows: %s", status, done, n,
        detail);
  /* step by step through interphase_update_dt, as the UMAT does it */
  double state[INTERPHASE_NSTATE], t_old[2] = {tra[0], tra[1]}, psi_old = psi[0], w = wd[0];
  memcpy(state, sta, sizeof state);
  int equal = 1, close = 1;
  for (size_t i = 1; i < n; ++i) {
    const double ds[2] = {sep[2 * i] - sep[2 * i - 2], sep[2 * i + 1] - sep[2 * i - 1]};
    const double s[2] = {sep[2 * i - 2] + ds[0], sep[2 * i - 1] + ds[1]};
    double traction[2], tangent[4], state_new[INTERPHASE_NSTATE], e;
    status = interphase_update_dt(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, s, tim[i] - tim[i - 1], traction,
                                  tangent, state_new, &e, detail, sizeof detail);
    if (status != INTERPHASE_STATUS_OK) {
      CHECK(0, "row %zu: interphase_update_dt status %d: %s", i, status, detail);
      return;
    }
    w = w + 0.5 * ((0.0 + (t_old[0] + traction[0]) * ds[0]) + (t_old[1] + traction[1]) * ds[1]) - (e - psi_old);
    equal = equal && traction[0] == tra[2 * i] && traction[1] == tra[2 * i + 1] && e == psi[i] && w == wd[i] &&
            memcmp(state_new, sta + INTERPHASE_NSTATE * i, sizeof state_new) == 0 &&
            memcmp(tangent, tan_ + 4 * i, sizeof tangent) == 0;
    close = close && close_to(tra[2 * i], ref[i][0], 1e-12, 1e-9) && close_to(tra[2 * i + 1], ref[i][1], 1e-12, 1e-9) &&
            close_to(sta[INTERPHASE_NSTATE * i], ref[i][2], 1e-12, 1e-9) && close_to(psi[i], ref[i][3], 1e-12, 1e-9) &&
            close_to(wd[i], ref[i][4], 1e-12, 1e-9);
    memcpy(state, state_new, sizeof state);
    t_old[0] = traction[0], t_old[1] = traction[1], psi_old = e;
  }
  CHECK(equal, "interphase_run differs from interphase_update_dt step by step");
  CHECK(close, "interphase_run differs from the driver's CSV %s", csv_path);

  /* a NaN at row 700: rows 0..699 computed, the failed row and the rows after it untouched */
  const size_t bad = 700;
  const double saved = sep[2 * bad];
  sep[2 * bad] = NAN;
  for (size_t i = 1; i < n; ++i) tra[2 * i] = -12345.0, psi[i] = -12345.0;
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, n, sep, tim, tra, NULL, sta, psi, wd, &done, detail,
                          sizeof detail);
  CHECK(status == INTERPHASE_STATUS_NONFINITE_SEPARATION && done == bad, "NaN at row %zu: status %d, rows_done %zu",
        bad, status, done);
  CHECK(strstr(detail, "row 700: separation s_N, s_T (mm) ") != NULL && strstr(detail, " NaN ") != NULL &&
            strstr(detail, ": not finite") != NULL,
        "detail does not name the row, its separation and the reason: %s", detail);
  CHECK(tra[2 * (bad - 1)] != -12345.0 && tra[2 * bad] == -12345.0 && psi[bad] == -12345.0 && psi[n - 1] == -12345.0,
        "rows from the failed one on were written");
  /* a finite separation beyond the admissible range at row 700: named as given, with the range */
  sep[2 * bad] = -2.0 * INTERPHASE_SEPARATION_MAX;
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, n, sep, tim, tra, NULL, sta, psi, wd, &done, detail,
                          sizeof detail);
  CHECK(status == INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE && done == bad &&
            strstr(detail, "row 700: separation s_N, s_T (mm) ") != NULL && strstr(detail, " -2.0000E+20 ") != NULL &&
            strstr(detail, ": beyond |s_i| <= ") != NULL,
        "separation -2e20 mm at row %zu: status %d, rows_done %zu: %s", bad, status, done, detail);
  sep[2 * bad] = saved;

  /* the starting row and the arguments are checked as interphase_update checks its inputs */
  double tra0 = tra[0];
  tra[0] = INFINITY;
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, sep, tim, tra, NULL, sta, psi, wd, &done, detail,
                          sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HOST_INPUT && done == 0 && strstr(detail, "row 0: separation (mm)") != NULL &&
            strstr(detail, "traction (MPa)    Infinity") != NULL && strstr(detail, "the rest within 1.0E+150") != NULL,
        "infinite starting traction, named: status %d: %s", status, detail);
  tra[0] = tra0;
  /* times whose step is beyond the largest double: refused before the step is formed (with the
   * overflow trap on, forming it would stop the caller) */
  const double wide_times[3] = {-1e308, 1e308, 1.5e308};
  feenableexcept(FE_OVERFLOW | FE_INVALID | FE_DIVBYZERO);
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, sep, wide_times, tra, NULL, sta, psi, wd, &done,
                          detail, sizeof detail);
  fedisableexcept(FE_OVERFLOW | FE_INVALID | FE_DIVBYZERO);
  CHECK(status == INTERPHASE_STATUS_BAD_TIME_INCREMENT && done == 1 && strstr(detail, "row 1: time ") != NULL &&
            strstr(detail, "with finite steps") != NULL,
        "a time step beyond the largest double: status %d, rows_done %zu: %s", status, done, detail);
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 0, sep, tim, tra, NULL, sta, psi, wd, &done, detail,
                          sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0, "nrows = 0: status %d", status);
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 4, 3, sep, tim, tra, NULL, sta, psi, wd, NULL, NULL, 0);
  CHECK(status == INTERPHASE_STATUS_BAD_NTENS, "ntens = 4: status %d", status);
  double bad_props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(bad_props);
  bad_props[4] = 1e-4;
  status = interphase_run(bad_props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, sep, tim, tra, NULL, sta, psi, wd, &done,
                          detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_SF_N && strstr(detail, "PROPS(5)") != NULL, "sf_N < s0_N: status %d: %s",
        status, detail);
  /* the UMAT's own options (a thin layer's thickness, PROPS[13]) are refused, as by interphase_update */
  double layer[INTERPHASE_NPROPS_SIMPLIFIED + 5] = {0.0};
  paper_props(layer);
  layer[13] = 2.0;
  status = interphase_run(layer, INTERPHASE_NPROPS_SIMPLIFIED + 5, 2, 3, sep, tim, tra, NULL, sta, psi, wd, &done,
                          detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_OPTION && strstr(detail, "UMAT only") != NULL,
        "layer thickness: status %d: %s", status, detail);
  /* viscous regularisation needs the times: NULL is refused, as by interphase_update */
  double viscous[INTERPHASE_NPROPS_SIMPLIFIED + 3];
  paper_props(viscous);
  viscous[9] = 0.0, viscous[10] = 0.0, viscous[11] = 0.5;
  static double sv[RUN_MAX_ROWS * INTERPHASE_NSTATE_VISCOUS];
  memset(sv, 0, sizeof sv);
  double zero2[4] = {0.0, 0.0, 0.001, 0.0}, tr2[4] = {0.0}, ps2[2] = {0.0}, wd2[2] = {0.0}, t2[2] = {0.0, 1.0};
  status = interphase_run(viscous, INTERPHASE_NPROPS_SIMPLIFIED + 3, 2, 2, zero2, NULL, tr2, NULL, sv, ps2, wd2, &done,
                          detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_TIME_INCREMENT && done == 1, "viscous without times: status %d", status);
  status = interphase_run(viscous, INTERPHASE_NPROPS_SIMPLIFIED + 3, 2, 2, zero2, t2, tr2, NULL, sv, ps2, wd2, &done,
                          detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == 2 && tr2[2] > 0.0, "viscous with times: status %d: %s", status,
        detail);
  printf("interphase_run: %zu rows, equal to interphase_update_dt step by step\n", n);
}

/* interphase_run_history: the paper's mixed history (separations only, a preload to s_N = -0.005
 * mm, 200 increments per segment) gives the driver's reference CSV; a shear test
 * under an imposed precompression holds Sigma_N to the tolerance and ends on the friction plateau;
 * an imposed traction beyond the peak, a bad history and arrays that are too short fail with
 * their statuses. */
static void test_run_history(const char *csv_path) {
  enum { ROWS = 1201 };
  static double ref[ROWS][7], o_t[ROWS], o_s[ROWS * 2], o_tr[ROWS * 2], o_st[ROWS * INTERPHASE_NSTATE], o_psi[ROWS],
      o_w[ROWS];
  static struct csv_row csv[ROWS];
  const size_t n = read_driver_csv(csv_path, csv, ROWS);
  for (size_t i = 0; i < n; ++i) {
    ref[i][0] = csv[i].t, ref[i][1] = csv[i].s_n, ref[i][2] = csv[i].s_t, ref[i][3] = csv[i].sig_n;
    ref[i][4] = csv[i].sig_t, ref[i][5] = csv[i].d, ref[i][6] = csv[i].w_dis;
  }
  CHECK(n == ROWS, "%zu rows read from %s, expected %d", n, csv_path, ROWS);
  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  const double time[7] = {0, 1, 2, 3, 4, 5, 6};
  const double value[14] = {-0.005, 0, -0.005, 0, -0.005, 0.05, -0.005, 0, -0.005, 0.08, -0.005, -0.05, -0.005, 0};
  size_t done = 0;
  char detail[257] = "";
  int status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 7, time, value, NULL, 200, 1e-12, 1,
                                      ROWS, o_t, o_s, o_tr, o_st, o_psi, o_w, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == n, "interphase_run_history: status %d, %zu rows: %s", status, done,
        detail);
  /* the rows' times and separations exactly; the rest within the reference files' tolerance
   * (tests/driver/reference/README.md: the files are compared across builds; bit for bit against
   * the driver of the same build: tests/python/test_paper_cases.py) */
  int same_rows = 1, close_values = 1;
  for (size_t i = 0; i < n && i < done; ++i) {
    same_rows &= o_t[i] == ref[i][0] && o_s[2 * i] == ref[i][1] && o_s[2 * i + 1] == ref[i][2];
    close_values &= close_to(o_tr[2 * i], ref[i][3], 1e-12, 1e-9) && close_to(o_tr[2 * i + 1], ref[i][4], 1e-12, 1e-9) &&
                    close_to(o_st[INTERPHASE_NSTATE * i], ref[i][5], 1e-12, 1e-9) &&
                    close_to(o_w[i], ref[i][6], 1e-12, 1e-9);
  }
  CHECK(same_rows, "interphase_run_history: the rows' times or separations differ from %s", csv_path);
  CHECK(close_values, "interphase_run_history: tractions, damage or energy differ from %s", csv_path);

  /* mixed control: Sigma_N = -0.5 MPa imposed, s_T driven to 0.1 mm (beyond sf_T) */
  const double t3[3] = {0, 1, 2};
  const double shear[6] = {0, 0, -0.5, 0, -0.5, 0.1};
  const int control[6] = {1, 0, 1, 0, 1, 0};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, t3, shear, control, 200, 1e-15, 1, ROWS,
                                  o_t, o_s, o_tr, o_st, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == 401, "shear under precompression: status %d, %zu rows: %s", status,
        done, detail);
  double drift = 0.0;
  for (size_t i = 200; i < done; ++i) drift = fmax(drift, fabs(o_tr[2 * i] + 0.5));
  CHECK(drift <= 1e-15, "Sigma_N left -0.5 MPa by %g MPa", drift);
  CHECK(done == 401 && close_to(o_tr[2 * 400 + 1], MU * 0.5, 0.0, 1e-12) && o_st[INTERPHASE_NSTATE * 400] == 1.0,
        "the friction plateau: Sigma_T = %g MPa, D = %g", o_tr[801], o_st[INTERPHASE_NSTATE * 400]);

  /* an imposed normal traction beyond the peak K_N s0_N: no solution */
  const double beyond[4] = {0, 0, 0.25, 0};
  const int both[4] = {1, 1, 1, 1};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, t3, beyond, both, 200, 1e-12, 1, ROWS,
                                  NULL, NULL, o_tr, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BEYOND_PEAK && strstr(detail, "beyond the peak the material can carry") &&
            done > 1 && done < 201 && o_tr[2 * (done - 1)] <= K_N * 0.00044,
        "beyond the peak: status %d, %zu rows: %s", status, done, detail);
  /* the message ends with the largest traction reached, just below the peak K_N s0_N = 0.212387 MPa */
  const char *reached = strstr(detail, "the largest |Sigma_N| reached is 0.21238");
  CHECK(reached != NULL && strcmp(reached + strlen(reached) - 5, " MPa)") == 0, "beyond the peak: the peak not named: %s",
        detail);

  /* the micromechanical model: an imposed Sigma_N, then Sigma_T at s_N = 0, raised to 5 MPa. The
   * fully damaged point's stiffnesses are round-off of zero (1e-13 MPa/mm); without the flat-
   * tangent test Newton met 5 MPa at s_N = 2e13 mm. The rows stop at the peak, below sf. */
  double micro[NPROPS_MICRO];
  micro_props(micro, 0.0);
  const double far[4] = {0, 0, 5.0, 0};
  status = interphase_run_history(micro, NPROPS_MICRO, 2, 2, t3, far, both, 100, 1e-12, 1, ROWS, NULL, o_s, o_tr,
                                  NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BEYOND_PEAK && done > 1 && o_s[2 * (done - 1)] < 0.04 &&
            o_tr[2 * (done - 1)] > 0.2 && o_tr[2 * (done - 1)] < 0.3,
        "micromechanical Sigma_N beyond the peak: status %d, %zu rows, last s_N %g mm, Sigma_N %g MPa: %s", status,
        done, done > 0 ? o_s[2 * (done - 1)] : 0.0, done > 0 ? o_tr[2 * (done - 1)] : 0.0, detail);
  const double far_shear[4] = {0, 0, 0, 5.0};
  const int shear_only[4] = {0, 1, 0, 1};
  status = interphase_run_history(micro, NPROPS_MICRO, 2, 2, t3, far_shear, shear_only, 100, 1e-12, 1, ROWS, NULL,
                                  o_s, o_tr, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BEYOND_PEAK && done > 1 && fabs(o_s[2 * (done - 1) + 1]) < 0.06 &&
            o_tr[2 * (done - 1) + 1] > 0.3 && o_tr[2 * (done - 1) + 1] < 0.4,
        "micromechanical Sigma_T beyond the peak: status %d, %zu rows, last s_T %g mm, Sigma_T %g MPa: %s", status,
        done, done > 0 ? o_s[2 * (done - 1) + 1] : 0.0, done > 0 ? o_tr[2 * (done - 1) + 1] : 0.0, detail);

  /* the fully damaged open crack (s_N = 0.1 mm) carries no tension (a flat tangent), but an
   * imposed compression closes it: Newton passes the flat state to the contact branch */
  const double open_then[6] = {0, 0, 0.1, 0, -1.0, 0};
  const int then_normal[6] = {0, 0, 0, 0, 1, 0};
  status = interphase_run_history(micro, NPROPS_MICRO, 2, 3, t3, open_then, then_normal, 50, 1e-12, 1, ROWS, NULL,
                                  o_s, o_tr, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == 101 && close_to(o_tr[2 * 100], -1.0, 1e-12, 0.0) &&
            o_s[2 * 100] < 0.0 && o_s[2 * 100] > -0.01,
        "recontact under an imposed compression: status %d, %zu rows: %s", status, done, detail);
  /* the simplified model's fully damaged open crack (s_N = 0.1 mm > sf_N): its normal stiffness is
   * exactly zero, so Newton has no step; the replay closes the crack at s_N = 0 first, and the
   * compression is met in contact at s_N = -1/K_N */
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, t3, open_then, then_normal, 50, 1e-12, 1,
                                  ROWS, NULL, o_s, o_tr, o_st, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == 101 && o_st[INTERPHASE_NSTATE * 50] == 1.0 &&
            close_to(o_tr[2 * 100], -1.0, 1e-12, 0.0) && close_to(o_s[2 * 100], -1.0 / K_N, 1e-12, 0.0),
        "simplified recontact under an imposed compression: status %d, %zu rows, D %g, s_N %g mm: %s", status, done,
        done > 50 ? o_st[INTERPHASE_NSTATE * 50] : -1.0, done > 100 ? o_s[2 * 100] : 0.0, detail);
  const double open_pull[6] = {0, 0, 0.1, 0, 0.1, 0};
  status = interphase_run_history(micro, NPROPS_MICRO, 2, 3, t3, open_pull, then_normal, 50, 1e-12, 1, ROWS, NULL,
                                  o_s, o_tr, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BEYOND_PEAK && strstr(detail, "is met only on a flat tangent in Sigma_N") && done == 51,
        "tension on the fully damaged open crack: status %d, %zu rows: %s", status, done, detail);

  /* an imposed compression has no peak: one that needs a separation beyond 1e20 mm is
   * INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE, naming the range (it was "beyond the peak ... the
   * largest |Sigma_N| reached is 0.00000 MPa") */
  const double crush[4] = {0, 0, -1e30, 0};
  const int normal_only[4] = {1, 0, 1, 0};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, t3, crush, normal_only, 10, 1e-12, 1, 200,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE && done == 1 && strstr(detail, "beyond the peak") == NULL &&
            strstr(detail, "the imposed traction Sigma_N = -0.976563E+26 MPa needs a separation beyond the admissible "
                           "range |s_N| <= 1.0E+20 mm") != NULL,
        "compression needing s_N beyond 1e20 mm: status %d, %zu rows: %s", status, done, detail);
  /* a separation beyond 1e20 mm in the history: refused before any update, naming row, component
   * and value (it ran, halved and named an interpolated value) */
  const double far_slip[6] = {0, 0, 0, 1e21, 0, 0};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, t3, far_slip, NULL, 10, 1e-12, 1, ROWS,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE && done == 0 &&
            strstr(detail, "value[3] (row 1, component 1: s_T) = 0.1E+22 mm is beyond the range the update admits") != NULL,
        "s_T = 1e21 mm in the history: status %d, %zu rows: %s", status, done, detail);
  /* an imposed traction beyond 1e150 MPa, as the driver's reader refuses it */
  const double huge_pull[4] = {0, 0, 1e200, 0};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, t3, huge_pull, normal_only, 10, 1e-12, 1,
                                  ROWS, NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 &&
            strstr(detail, "value[2] (row 1, component 0: Sigma_N) = 0.1E+201 MPa is beyond the range the replay admits") != NULL,
        "Sigma_N = 1e200 MPa in the history: status %d, %zu rows: %s", status, done, detail);

  /* a bad history, arrays that are too short */
  const double nan_value[6] = {0, 0, 0, NAN, 0, 0};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, t3, nan_value, NULL, 10, 1e-12, 1, ROWS,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0
            && strstr(detail, "value[3] (row 1, component 1: s_T) = NaN is not finite"),
        "a NaN in the history: status %d: %s", status, detail);
  const double back[3] = {0, 2, 1};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, back, shear, control, 10, 1e-12, 1, ROWS,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 && strstr(detail, "time[2]"),
        "times not increasing: status %d: %s", status, detail);
  /* finite times whose difference is not: the replay interpolates the time within the step */
  const double wide[3] = {-1e308, 1e308, 1.5e308};
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, wide, shear, control, 10, 1e-12, 1, ROWS,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 && strstr(detail, "time[1]") &&
            strstr(detail, "the time step from time[0]") && strstr(detail, "is not finite"),
        "a time step beyond the largest double: status %d: %s", status, detail);
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 3, t3, shear, control, 200, 1e-15, 1, 10,
                                  NULL, NULL, o_tr, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OUTPUT_FULL && done == 10, "capacity 10: status %d, %zu rows: %s", status, done,
        detail);
  printf("interphase_run_history: the driver's %zu rows; mixed control, beyond the peak, bad input\n", n);
}

/* 7. Arguments: every array an entry point dereferences, when NULL, gives
 * INTERPHASE_STATUS_NULL_ARGUMENT and a detail naming it (no crash, also with a NULL detail); a
 * size_t of 2^63 or more is read as the unsigned value it is (refused as too large, named), and
 * a detail of that length is written; interphase_run_history with more rows than memory holds
 * returns a status (the process goes on). */
static void expect_null(int status, const char *detail, const char *name, const char *call) {
  char want[64];
  snprintf(want, sizeof want, "%s is NULL", name);
  CHECK(status == INTERPHASE_STATUS_NULL_ARGUMENT && strncmp(detail, want, strlen(want)) == 0,
        "%s with %s NULL: status %d, \"%s\"", call, name, status, detail);
}

static void test_arguments(void) {
  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  const double state[INTERPHASE_NSTATE] = {0.0}, s[2] = {0.001, 0.0005};
  double t[2], k[4], st[INTERPHASE_NSTATE], psi;
  char detail[257];
  const char *names[7] = {"props", "state_old", "separation", "traction", "tangent", "state_new", "stored_energy"};
  for (int which = 0; which < 7; ++which) {
    const double *a[7] = {props, state, s, t, k, st, &psi};
    a[which] = NULL;
    strcpy(detail, "untouched");
    int status = interphase_update(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, a[1], a[2], (double *)a[3], (double *)a[4],
                                   (double *)a[5], (double *)a[6], detail, sizeof detail);
    expect_null(status, detail, names[which], "interphase_update");
    status = interphase_update(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, a[1], a[2], (double *)a[3], (double *)a[4],
                               (double *)a[5], (double *)a[6], NULL, 0);
    CHECK(status == INTERPHASE_STATUS_NULL_ARGUMENT, "interphase_update, %s NULL, no detail: %d", names[which], status);
    strcpy(detail, "untouched");
    status = interphase_update_dt(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, a[1], a[2], 0.1, (double *)a[3],
                                  (double *)a[4], (double *)a[5], (double *)a[6], detail, sizeof detail);
    expect_null(status, detail, names[which], "interphase_update_dt");
  }

  /* interphase_run: its arrays (time, tangent and rows_done may be NULL) */
  double sep[4] = {0.0, 0.0, 0.001, 0.0}, tim[2] = {0.0, 1.0}, tra[4] = {0.0}, sta[2 * INTERPHASE_NSTATE] = {0.0},
         ps[2] = {0.0}, wd[2] = {0.0};
  size_t done = 99;
  const char *run_names[6] = {"props", "separation", "traction", "state", "stored_energy", "dissipated_energy"};
  for (int which = 0; which < 6; ++which) {
    double *a[6] = {props, sep, tra, sta, ps, wd};
    a[which] = NULL;
    strcpy(detail, "untouched");
    int status = interphase_run(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, a[1], tim, a[2], NULL, a[3], a[4], a[5],
                                &done, detail, sizeof detail);
    expect_null(status, detail, run_names[which], "interphase_run");
    CHECK(done == 0, "interphase_run, %s NULL: rows_done %zu", run_names[which], done);
    status = interphase_run(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, a[1], NULL, a[2], NULL, a[3], a[4], a[5], NULL,
                            NULL, 0);
    CHECK(status == INTERPHASE_STATUS_NULL_ARGUMENT, "interphase_run, %s NULL, no detail: %d", run_names[which],
          status);
  }
  int status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, sep, NULL, tra, NULL, sta, ps, wd, &done,
                              detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == 2, "interphase_run with every array: status %d: %s", status, detail);

  /* interphase_run_history: props, time and value (the rest may be NULL) */
  const double hv[4] = {0.0, 0.0, 0.001, 0.0};
  const char *history_names[3] = {"props", "time", "value"};
  for (int which = 0; which < 3; ++which) {
    const double *a[3] = {props, tim, hv};
    a[which] = NULL;
    strcpy(detail, "untouched");
    status = interphase_run_history(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, a[1], a[2], NULL, 2, 1e-12, 1, 10, NULL,
                                    NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
    expect_null(status, detail, history_names[which], "interphase_run_history");
    status = interphase_run_history(a[0], INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, a[1], a[2], NULL, 2, 1e-12, 1, 10, NULL,
                                    NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, 0);
    CHECK(status == INTERPHASE_STATUS_NULL_ARGUMENT, "interphase_run_history, %s NULL, no detail: %d",
          history_names[which], status);
  }

  /* sizes of 2^63 and more: the unsigned value, refused as too large */
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, SIZE_MAX, sep, tim, tra, NULL, sta, ps, wd, &done,
                          detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 &&
            strstr(detail, "nrows = 18446744073709551615 is too large") != NULL,
        "interphase_run, nrows = SIZE_MAX: status %d: %s", status, detail);
  status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, (size_t)1 << 63, sep, tim, tra, NULL, sta, ps, wd,
                          &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && strstr(detail, "nrows = 9223372036854775808 is too large") != NULL,
        "interphase_run, nrows = 2^63: status %d: %s", status, detail);
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, SIZE_MAX, tim, hv, NULL, 2, 1e-12, 1, 10,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 &&
            strstr(detail, "nrows = 18446744073709551615 is too large") != NULL,
        "interphase_run_history, nrows = SIZE_MAX: status %d: %s", status, detail);
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, 2, tim, hv, NULL, 2, 1e-12, 1, SIZE_MAX,
                                  NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 &&
            strstr(detail, "capacity = 18446744073709551615 rows is too large") != NULL,
        "interphase_run_history, capacity = SIZE_MAX: status %d: %s", status, detail);
  /* an nrows below that bound but beyond any memory (a wrong size_t, as a rule): a status, not
   * the Fortran run time's error and the end of the process */
  status = interphase_run_history(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, (size_t)100000000000000000ULL, tim, hv, NULL,
                                  2, 1e-12, 1, 10, NULL, NULL, NULL, NULL, NULL, NULL, NULL, &done, detail,
                                  sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_HISTORY && done == 0 &&
            strstr(detail, "nrows = 100000000000000000: no memory for so many rows") != NULL,
        "interphase_run_history, nrows = 1e17: status %d: %s", status, detail);
  /* a detail of length SIZE_MAX is written (the message and its NUL) */
  strcpy(detail, "the previous message");
  status = interphase_update(props, 8, 2, state, s, t, k, st, &psi, detail, SIZE_MAX);
  CHECK(status == INTERPHASE_STATUS_BAD_NPROPS && strstr(detail, "previous") == NULL && strlen(detail) > 0,
        "detail_len = SIZE_MAX: status %d, \"%s\"", status, detail);
  char msg[64] = "xxxx";
  size_t len = interphase_status_message(INTERPHASE_STATUS_OK, msg, SIZE_MAX);
  CHECK(len == strlen("success") && strcmp(msg, "success") == 0, "status message, len = SIZE_MAX: \"%s\"", msg);
  printf("arguments: NULL arrays named, sizes of 2^63 and more read unsigned\n");
}

/* interphase_update_increment: the separation at the start of the increment reaches the update as
 * in interphase_run (the same numbers, bit for bit, along a path whose fifth row closes the crack
 * within its increment), the closure ends where the faces met, and separation_old and dt are
 * checked. */
static void test_update_increment(void) {
  double props[INTERPHASE_NPROPS_SIMPLIFIED];
  paper_props(props);
  enum { N = 6 };
  const double path[N][2] = {{0.0, 0.0},    {0.001, 0.0015},  {0.002, 0.003},
                             {0.003, 0.004}, {-0.001, 0.0005}, {-0.0012, 0.0}};
  double tra[N * 2] = {0}, sta[N * INTERPHASE_NSTATE] = {0}, psi[N] = {0}, wd[N] = {0};
  size_t done = 0;
  char detail[257] = "";
  int status = interphase_run(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, N, &path[0][0], NULL, tra, NULL, sta, psi, wd,
                              &done, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && done == N, "increment path: interphase_run status %d: %s", status, detail);
  double state[INTERPHASE_NSTATE] = {0}, t[2], k[4], next[INTERPHASE_NSTATE], e;
  for (int i = 1; i < N; ++i) {
    status = interphase_update_increment(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, state, path[i - 1], path[i], NULL, t, k,
                                         next, &e, detail, sizeof detail);
    CHECK(status == INTERPHASE_STATUS_OK, "increment row %d: status %d: %s", i, status, detail);
    CHECK(memcmp(t, &tra[2 * i], sizeof t) == 0 && memcmp(next, &sta[INTERPHASE_NSTATE * i], sizeof next) == 0 &&
              e == psi[i],
          "increment row %d: traction (%.17g, %.17g), not interphase_run's (%.17g, %.17g)", i, t[0], t[1], tra[2 * i],
          tra[2 * i + 1]);
    memcpy(state, next, sizeof state);
  }
  /* row 4: open at (0.003, 0.004) mm, closed at (-0.001, 0.0005): s_N = 0 at s_T = 1.375 um, where the
   * simplified model's faces stick with the slip s_T */
  const double *closed = &sta[INTERPHASE_NSTATE * 4];
  CHECK(sta[INTERPHASE_NSTATE * 3 + 3] == 1.0 && closed[3] == 2.0 && close_to(closed[1], 1.375e-3, 0.0, 1e-14),
        "increment closure: regimes %g -> %g, slip %.17g mm (1.375e-3 expected)", sta[INTERPHASE_NSTATE * 3 + 3],
        closed[3], closed[1]);
  /* interphase_update, without the start: the state's slip, another closed state */
  status = interphase_update(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, &sta[INTERPHASE_NSTATE * 3], path[4], t, k, next, &e,
                             NULL, 0);
  CHECK(status == INTERPHASE_STATUS_OK && fabs(t[1] - tra[2 * 4 + 1]) > 0.1,
        "increment closure without the start: Sigma_T %.17g against %.17g", t[1], tra[2 * 4 + 1]);

  const double virgin[INTERPHASE_NSTATE] = {0};
  status = interphase_update_increment(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, virgin, NULL, path[1], NULL, t, k, next,
                                       &e, detail, sizeof detail);
  expect_null(status, detail, "separation_old", "interphase_update_increment");
  const double nan_start[2] = {NAN, 0.0};
  status = interphase_update_increment(props, INTERPHASE_NPROPS_SIMPLIFIED, 2, virgin, nan_start, path[1], NULL, t, k,
                                       next, &e, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_NONFINITE_SEPARATION && strstr(detail, "separation_old") != NULL,
        "increment: a NaN start gave status %d: %s", status, detail);
  double viscous[INTERPHASE_NPROPS_SIMPLIFIED + 3];
  memcpy(viscous, props, sizeof props);
  viscous[9] = 0.0, viscous[10] = 0.0, viscous[11] = 0.5;
  double vstate[INTERPHASE_NSTATE_VISCOUS] = {0}, vnext[INTERPHASE_NSTATE_VISCOUS];
  status = interphase_update_increment(viscous, INTERPHASE_NPROPS_SIMPLIFIED + 3, 2, vstate, path[0], path[1], NULL, t, k,
                                       vnext, &e, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_BAD_TIME_INCREMENT, "increment: a viscous material without dt gave status %d",
        status);
  const double dt = 0.1;
  status = interphase_update_increment(viscous, INTERPHASE_NPROPS_SIMPLIFIED + 3, 2, vstate, path[0], path[1], &dt, t, k,
                                       vnext, &e, detail, sizeof detail);
  CHECK(status == INTERPHASE_STATUS_OK && vnext[0] > 0.0, "increment: viscous, dt = 0.1 s: status %d, D %g: %s", status,
        vnext[0], detail);
}

int main(int argc, char **argv) {
  if (argc == 4 && strcmp(argv[1], "--load") == 0) {
    test_load_table(argv[2], argv[3]);
    test_load_rcurve();
  } else if (argc == 2) {
    test_mixed_history(argv[1]);
    test_energy_in_place_and_restart(argv[1]);
    test_failures();
    test_run(argv[1]);
    test_run_history(argv[1]);
    test_arguments();
    test_update_increment();
  } else {
    fprintf(stderr, "usage: %s <tests/driver/reference/mixed.csv>\n"
                    "       %s --load <tables/paper.dat> <tables/paper-resolution.dat>\n", argv[0], argv[0]);
    return 2;
  }
  printf("%d checks, %d failed\n", checks, failures);
  return failures == 0 ? 0 : 1;
}
