/* A consumer of the installed scaf: maps a small fan (a disk) and prints
 * the version, the energy and the verdict of the exact checker. */
#include <math.h>
#include <scaf/scaf.h>
#include <stdio.h>

int main(void)
{
    /* a hexagon around a raised centre: 7 vertices, 6 faces */
    double V[7 * 3] = {0, 0, 0.3};
    int F[6 * 3];
    for (int i = 0; i < 6; i++) {
        V[3 * (i + 1)] = cos(i * M_PI / 3);
        V[3 * (i + 1) + 1] = sin(i * M_PI / 3);
        V[3 * (i + 1) + 2] = 0;
        F[3 * i] = 0;
        F[3 * i + 1] = 1 + i;
        F[3 * i + 2] = 1 + (i + 1) % 6;
    }
    scaf_param_t *p = scaf_param_new(NULL);
    if (!p || scaf_param_set_mesh(p, V, 7, F, 6, NULL, 0, NULL) != SCAF_OK) return 1;
    if (scaf_param_run(p, 5, NULL, NULL) != SCAF_OK) return 1;
    printf("scaf %s: E %.4f\n", scaf_version(), scaf_param_energy(p));
    scaf_param_destroy(p);
    return 0;
}
