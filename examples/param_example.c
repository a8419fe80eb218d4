/* examples/param_example: a bijective parametrization through the public
 * C API only.
 *
 *     param_example
 *
 * Builds a bumpy square grid (a disk, one chart), computes its UV map with
 * scaf_param_* (Tutte start, then SCAF iterations, bijective after every
 * one), prints the energy per iteration and checks from outside that every
 * triangle is counter-clockwise in UV. Exit status 0 on success.
 *
 * Build against an installed scaf:
 *     cc param_example.c $(pkg-config --cflags --libs scaf) -lm -o param_example
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <scaf/scaf.h>

static int on_iteration(const scaf_iteration_info_t *info, void *user)
{
    (void)user;
    printf("  iteration %2d  E %.6f  step %.3f\n", info->iteration, info->energy, info->step);
    return 0; /* nonzero would stop the run (SCAF_ERR_CANCELLED) */
}

int main(void)
{
    enum { R = 12 };
    int nv = (R + 1) * (R + 1), nf = 2 * R * R;
    double *V = malloc(sizeof(double) * 3 * (size_t)nv), *UV = NULL;
    int *F = malloc(sizeof(int) * 3 * (size_t)nf), *FT = NULL, rc = 1;
    if (!V || !F) return 1;
    for (int j = 0; j <= R; j++)
        for (int i = 0; i <= R; i++) {
            double x = (double)i / R, y = (double)j / R, *v = V + 3 * (j * (R + 1) + i);
            v[0] = x, v[1] = y, v[2] = 0.4 * sin(4.0 * x) * sin(3.0 * y);
        }
    for (int j = 0, f = 0; j < R; j++)
        for (int i = 0; i < R; i++, f += 2) {
            int a = j * (R + 1) + i, b = a + 1, c = a + R + 1, d = c + 1, *t = F + 3 * f;
            t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
        }

    scaf_options_t opt = scaf_options_default();
    opt.max_iterations = 10;
    scaf_param_t *p = scaf_param_new(&opt);
    if (!p) { /* out of memory, or an option out of range: the check says which */
        char why[256] = "out of memory";
        scaf_options_check(&opt, why, sizeof why);
        fprintf(stderr, "%s\n", why);
        return 1;
    }
    scaf_status st = scaf_param_set_mesh(p, V, nv, F, nf, NULL, 0, NULL);
    double e0 = scaf_param_energy(p);
    if (st == SCAF_OK) st = scaf_param_run(p, 0, on_iteration, NULL);
    if (st != SCAF_OK) {
        fprintf(stderr, "param_example: %s: %s\n", scaf_status_name(st), scaf_param_error(p));
        goto done;
    }
    int nuv = scaf_param_uv_count(p);
    UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    FT = malloc(sizeof(int) * 3 * (size_t)nf);
    if (!UV || !FT || scaf_param_get_uv(p, UV, FT) != SCAF_OK) goto done;
    for (int f = 0; f < nf; f++) {
        const double *a = UV + 2 * FT[3 * f], *b = UV + 2 * FT[3 * f + 1],
                     *c = UV + 2 * FT[3 * f + 2];
        if (!((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0.0)) {
            fprintf(stderr, "param_example: triangle %d is not counter-clockwise\n", f);
            goto done;
        }
    }
    double e1 = scaf_param_energy(p);
    printf("param: %d UVs, %d iterations (stop reason: %s), E %.6f -> %.6f\n", nuv,
           scaf_param_iterations(p), scaf_stop_reason_name(scaf_param_stop_reason(p)), e0, e1);
    rc = e1 < e0 ? 0 : 1;
done:
    scaf_param_destroy(p);
    free(V);
    free(F);
    free(UV);
    free(FT);
    return rc;
}
