/* A C program that uses an installed interphase through its C API (include/interphase.h):
 * one update of the simplified model with the paper's Table 1 data, in mode I below the peak,
 * where the traction is K_N s_N. Exit status 0 when it is. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "interphase.h"

int main(void)
{
    const double props[9] = {1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.69742679680568, 198.75776397515528};
    double state_old[8], state_new[8], s[2] = {0.0002, 0.0}, t[2], k[4], psi;
    memset(state_old, 0, sizeof state_old);
    char detail[257];
    int status = interphase_update(props, 9, 2, state_old, s, t, k, state_new, &psi, detail, sizeof detail);
    if (status != 0) {
        char text[256];
        interphase_status_message(status, text, sizeof text);
        fprintf(stderr, "consumer_c: interphase_update failed: %s: %s\n", text, detail);
        return 1;
    }
    if (fabs(t[0] - 482.69742679680568 * 0.0002) > 1e-12) {
        fprintf(stderr, "consumer_c: traction %.17g, expected K_N s_N\n", t[0]);
        return 1;
    }
    printf("consumer_c: Sigma_N = %.6f MPa (K_N s_N)\n", t[0]);
    return 0;
}
