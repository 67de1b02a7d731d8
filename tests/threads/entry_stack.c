/* Stack that one call of the Abaqus entry points takes from the calling thread (docs/abaqus.md,
 * 'Thread safety'): a host that starts its own threads sizes their stacks from the figures the
 * docs give, so they must hold. Each case runs in a thread of its own on a 1 MiB stack this
 * program fills with a pattern; the deepest byte changed, less that of a thread that calls
 * nothing (the thread's descriptor and TLS), is the call's stack. The VUMAT: the vectorised block
 * updates (simplified, micromechanical on the built-in table, 2-D and 3-D), the point update
 * (fracture law, viscous regularisation) and a block with a failed point (the warning through
 * the message hook); the UMAT: both models, 2-D and 3-D, and a failed call. Fails if a VUMAT call
 * takes more than VUMAT_STACK_MAX or a UMAT call more than UMAT_STACK_MAX bytes: the figures
 * docs/abaqus.md states. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the bounds docs/abaqus.md states ('Thread safety') */
#define VUMAT_STACK_MAX (192 * 1024)
#define UMAT_STACK_MAX (16 * 1024)
#define STACK_SIZE (1024 * 1024)
#define PATTERN 0xA5

void vumat_(const int *nblock, const int *ndir, const int *nshr, const int *nstatev, const int *nfieldv,
            const int *nprops, const int *lanneal, const double *steptime, const double *totaltime,
            const double *dt, const char *cmname, const double *coordmp, const double *charlength,
            const double *props, const double *density, const double *straininc, const double *relspininc,
            const double *tempold, const double *stretchold, const double *defgradold, const double *fieldold,
            const double *stressold, const double *stateold, const double *enerinternold,
            const double *enerinelasold, const double *tempnew, const double *stretchnew,
            const double *defgradnew, const double *fieldnew, double *stressnew, double *statenew,
            double *enerinternnew, double *enerinelasnew, size_t cmname_len);
void umat_(double *stress, double *statev, double *ddsdde, double *sse, double *spd, double *scd, double *rpl,
           double *ddsddt, double *drplde, double *drpldt, const double *stran, const double *dstran,
           const double *time, const double *dtime, const double *temp, const double *dtemp,
           const double *predef, const double *dpred, const char *cmname, const int *ndi, const int *nshr,
           const int *ntens, const int *nstatv, const double *props, const int *nprops, const double *coords,
           const double *drot, double *pnewdt, const double *celent, const double *dfgrd0,
           const double *dfgrd1, const int *noel, const int *npt, const int *layer, const int *kspt,
           const int *jstep, const int *kinc, size_t cmname_len);

enum { NONE, SIMPLIFIED, MICRO, FRACTURE, VISCOUS };
struct call_case {
   const char *name;
   int vumat, material, nshr, fail;
};

static const double SIMPLIFIED_PROPS[] = {1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.6974268, 198.757764};
static const double MICRO_PROPS[] = {2, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 0};
static const double FRACTURE_PROPS[] = {1, 2, 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.6974268, 198.757764,
                                        0.1, 1, 0.005, 0.0085};
static const double VISCOUS_PROPS[] = {1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.6974268, 198.757764,
                                       0, 0, 1e-4};

static int material_props(int material, double *props) {
   const double *p = SIMPLIFIED_PROPS;
   size_t n = sizeof SIMPLIFIED_PROPS;
   if (material == MICRO) { p = MICRO_PROPS; n = sizeof MICRO_PROPS; }
   if (material == FRACTURE) { p = FRACTURE_PROPS; n = sizeof FRACTURE_PROPS; }
   if (material == VISCOUS) { p = VISCOUS_PROPS; n = sizeof VISCOUS_PROPS; }
   memcpy(props, p, n);
   return (int)(n / sizeof(double));
}

/* a case whose call did not end as its name says (a failure where none was meant, or none where
 * one was): the stack it measured is not that of the path it names (exit status 2) */
static void wrong_outcome(const struct call_case *c, const char *what) {
   fprintf(stderr, "entry_stack: %s: %s, so its stack is not that of the path it names\n", c->name, what);
   exit(2);
}

#define NB 64
static void call_vumat(const struct call_case *c) {
   static const int ndir = 1, nstatev = 9, nfieldv = 1, lanneal = 0;
   const int nblock = NB, nshr = c->nshr;
   double props[16];
   const int nprops = material_props(c->material, props);
   /* the host's arrays on the heap: only the library's stack is measured */
   double *a = calloc((size_t)NB * 64, sizeof(double));
   double *coord = a, *charlength = coord + 3 * NB, *density = charlength + NB, *strain_inc = density + NB,
          *relspin = strain_inc + 3 * NB, *temp = relspin + 2 * NB, *stretch = temp + NB, *defgrad = stretch + 3 * NB,
          *field = defgrad + 5 * NB, *stress_old = field + NB, *stress_new = stress_old + 3 * NB,
          *state_old = stress_new + 3 * NB, *state_new = state_old + 9 * NB, *e_int_old = state_new + 9 * NB,
          *e_inel_old = e_int_old + NB, *e_int_new = e_inel_old + NB, *e_inel_new = e_int_new + NB;
   const double step_time = 1e-3, total_time = 1e-3, dt = 1e-3;
   char cmname[80];
   memset(cmname, ' ', sizeof cmname);
   for (int i = 0; i < NB; i++) {
      density[i] = 2e-9;
      charlength[i] = 1;
      strain_inc[i] = 1e-3 * cos(i);
      strain_inc[NB + i] = 5e-4 * sin(i);
      strain_inc[2 * NB + i] = 3e-4;
   }
   if (c->fail) strain_inc[0] = 1e30;
   vumat_(&nblock, &ndir, &nshr, &nstatev, &nfieldv, &nprops, &lanneal, &step_time, &total_time, &dt, cmname,
          coord, charlength, props, density, strain_inc, relspin, temp, stretch, defgrad, field, stress_old,
          state_old, e_int_old, e_inel_old, temp, stretch, defgrad, field, stress_new, state_new, e_int_new,
          e_inel_new, sizeof cmname);
   /* STATEV(9), the failure flag: 1 at the failed point only, else 0 */
   for (int i = 0; i < NB; i++) {
      const double flag = state_new[8 * NB + i];
      if (c->fail && i == 0 && flag != 1.0) wrong_outcome(c, "its first point did not fail");
      if ((!c->fail || i > 0) && flag != 0.0) wrong_outcome(c, "a point failed");
      if ((!c->fail || i > 0) && !isfinite(stress_new[i])) wrong_outcome(c, "a traction is not finite");
   }
   free(a);
}

static void call_umat(const struct call_case *c) {
   static const int ndi = 1, nstatv = 5, noel = 1, npt = 1, layer = 1, kspt = 1, jstep[4] = {1, 0, 0, 0}, kinc = 1;
   const int nshr = c->nshr, ntens = 1 + c->nshr;
   double props[16];
   const int nprops = material_props(c->material, props);
   double *a = calloc(128, sizeof(double));
   double *stress = a, *statev = stress + 3, *ddsdde = statev + 5, *ddsddt = ddsdde + 9, *drplde = ddsddt + 3,
          *stran = drplde + 3, *dstran = stran + 3, *time = dstran + 3, *coords = time + 2, *drot = coords + 3,
          *dfgrd = drot + 9, *scalars = dfgrd + 9;
   const double dtime = 1e-3, zero = 0, celent = 1;
   double pnewdt = 1e36;
   char cmname[80];
   memset(cmname, ' ', sizeof cmname);
   dstran[0] = 1e-3;
   dstran[1] = 5e-4;
   dstran[2] = 3e-4;
   if (c->fail) dstran[0] = NAN;
   umat_(stress, statev, ddsdde, &scalars[0], &scalars[1], &scalars[2], &scalars[3], ddsddt, drplde, &scalars[4],
         stran, dstran, time, &dtime, &zero, &zero, &zero, &zero, cmname, &ndi, &nshr, &ntens, &nstatv, props,
         &nprops, coords, drot, &pnewdt, &celent, dfgrd, dfgrd, &noel, &npt, &layer, &kspt, jstep, &kinc,
         sizeof cmname);
   /* a failed call asks for a smaller increment (PNEWDT < 1); an update leaves PNEWDT >= 1 */
   if (c->fail && !(pnewdt < 1)) wrong_outcome(c, "the call did not fail");
   if (!c->fail && !(pnewdt >= 1)) wrong_outcome(c, "the call failed");
   if (!c->fail && !(stress[0] > 0)) wrong_outcome(c, "the opening gave no normal traction");
   free(a);
}

static void *run_case(void *arg) {
   const struct call_case *c = arg;
   if (c->material == NONE) return NULL;
   if (c->vumat)
      call_vumat(c);
   else
      call_umat(c);
   return NULL;
}

/* bytes of a fresh 1 MiB stack that running `c` in a thread on it changed */
static size_t stack_used(const struct call_case *c) {
   unsigned char *stack = aligned_alloc(4096, STACK_SIZE);
   pthread_attr_t attr;
   pthread_t thread;
   size_t untouched = 0;
   if (!stack) { perror("aligned_alloc"); exit(2); }
   memset(stack, PATTERN, STACK_SIZE);
   pthread_attr_init(&attr);
   if (pthread_attr_setstack(&attr, stack, STACK_SIZE) || pthread_create(&thread, &attr, run_case, (void *)c) ||
       pthread_join(thread, NULL)) {
      fprintf(stderr, "entry_stack: cannot run a thread on a stack of its own\n");
      exit(2);
   }
   pthread_attr_destroy(&attr);
   while (untouched < STACK_SIZE && stack[untouched] == PATTERN) untouched++;
   free(stack);
   return STACK_SIZE - untouched;
}

int main(void) {
   static const struct call_case cases[] = {
      {"VUMAT simplified block, 2-D", 1, SIMPLIFIED, 1, 0},
      {"VUMAT simplified block, 3-D", 1, SIMPLIFIED, 2, 0},
      {"VUMAT micromechanical block (built-in table), 2-D", 1, MICRO, 1, 0},
      {"VUMAT micromechanical block (built-in table), 3-D", 1, MICRO, 2, 0},
      {"VUMAT fracture law (point update), 2-D", 1, FRACTURE, 1, 0},
      {"VUMAT viscous regularisation (point update), 3-D", 1, VISCOUS, 2, 0},
      {"VUMAT micromechanical block with a failed point", 1, MICRO, 1, 1},
      {"UMAT simplified, 2-D", 0, SIMPLIFIED, 1, 0},
      {"UMAT micromechanical, 3-D", 0, MICRO, 2, 0},
      {"UMAT fracture law, 2-D", 0, FRACTURE, 1, 0},
      {"UMAT viscous regularisation, 2-D", 0, VISCOUS, 1, 0},
      {"UMAT micromechanical, failed call", 0, MICRO, 1, 1},
   };
   const struct call_case nothing = {"a thread that calls nothing", 0, NONE, 1, 0};
   const size_t base = stack_used(&nothing);
   size_t vumat_most = 0, umat_most = 0;
   int failures = 0;
   printf("a thread that calls nothing: %zu bytes (subtracted below)\n", base);
   for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
      const size_t used = stack_used(&cases[i]) - base;
      const size_t bound = cases[i].vumat ? VUMAT_STACK_MAX : UMAT_STACK_MAX;
      printf("%-52s %7zu bytes (%.1f KB)%s\n", cases[i].name, used, used / 1024.0, used > bound ? "  TOO MUCH" : "");
      if (used > bound) failures++;
      if (cases[i].vumat && used > vumat_most) vumat_most = used;
      if (!cases[i].vumat && used > umat_most) umat_most = used;
   }
   printf("most: VUMAT %.1f KB (docs: at most %d KB), UMAT %.1f KB (docs: at most %d KB)\n", vumat_most / 1024.0,
          VUMAT_STACK_MAX / 1024, umat_most / 1024.0, UMAT_STACK_MAX / 1024);
   if (failures) printf("entry_stack: %d call(s) take more stack than docs/abaqus.md states\n", failures);
   return failures ? 1 : 0;
}
