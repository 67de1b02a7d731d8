/*
 * Instruction counts of the C entry interphase_run_history against interphase_run (callgrind;
 * docs/performance.md, 'Python package'): the paper's mixed history (simplified model, Table 1
 * data), 3 000 increments per segment, 18 000 steps.
 *
 *   gcc -O2 -Iinclude tools/bench-run-history.c -Lbuild/release -linterphase \
 *       -Wl,-rpath,$PWD/build/release -o bench-run-history
 *   valgrind --tool=callgrind ./bench-run-history 0   # interphase_run_history alone
 *   valgrind --tool=callgrind ./bench-run-history 1   # then interphase_run over its rows
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "interphase.h"

int main(int argc, char **argv) {
  const int both = argc > 1 && atoi(argv[1]) == 1;
  const int increments = 3000;
  const double props[9] = {1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 544000.0 / 1127.0, 32000.0 / 161.0};
  const double time[7] = {0, 1, 2, 3, 4, 5, 6};
  const double value[14] = {-0.005, 0, -0.005, 0, -0.005, 0.05, -0.005, 0, -0.005, 0.08, -0.005, -0.05, -0.005, 0};
  const size_t capacity = 1 + 6 * (size_t)increments;
  size_t done = 0;
  double *t = malloc(capacity * sizeof *t), *s = malloc(2 * capacity * sizeof *s),
         *tr = malloc(2 * capacity * sizeof *tr), *st = malloc(INTERPHASE_NSTATE * capacity * sizeof *st),
         *psi = malloc(capacity * sizeof *psi), *w = malloc(capacity * sizeof *w);
  char detail[257] = "";
  if (!(t && s && tr && st && psi && w)) return 1;
  int status = interphase_run_history(props, 9, 2, 7, time, value, NULL, increments, 1e-12, 1, capacity, t, s, tr,
                                      st, psi, w, NULL, &done, detail, sizeof detail);
  if (both && status == INTERPHASE_STATUS_OK) {
    memset(tr + 2, 0, 2 * (capacity - 1) * sizeof *tr);
    status = interphase_run(props, 9, 2, capacity, s, t, tr, NULL, st, psi, w, &done, detail, sizeof detail);
  }
  printf("status %d, %zu rows, last Sigma_T %.17g %s\n", status, done, tr[2 * capacity - 1], detail);
  return status == INTERPHASE_STATUS_OK ? 0 : 1;
}
