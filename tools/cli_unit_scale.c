/* tools/cli_unit_scale: see cli_unit_scale.h. */
#include "cli_unit_scale.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#include "exit_codes.h"
#include "geom/coord_scale.h"

int cli_unit_scale(const char *cmd, const char *in, mesh *m, int *e)
{
    *e = coord_scale_exponent(m->V, 3, 3 * (size_t)m->nf, m->F);
    /* inputs in everyday units are left exactly as they are (the same
     * bits as before); only those whose squares would leave the range */
    if (*e >= -CLI_UNIT_SCALE_SAFE && *e <= CLI_UNIT_SCALE_SAFE) {
        *e = 0;
        return EXIT_OK;
    }
    double lo = INFINITY, hi = 0.0;
    for (size_t i = 0; i < 3 * (size_t)m->nv; i++) {
        double a = fabs(m->V[i]);
        if (a > 0.0 && a < lo) lo = a;
        if (a > hi) hi = a;
    }
    for (size_t i = 0; i < 3 * (size_t)m->nv; i++) {
        double s = ldexp(m->V[i], -*e);
        if (m->V[i] != 0.0 && fabs(s) < DBL_MIN) {
            fprintf(stderr,
                    "scaf %s: %s: the coordinates range from %g to %g in magnitude: more orders "
                    "of magnitude than a double holds at once (the smallest would lose its "
                    "precision at the largest's scale)\n",
                    cmd, in, lo, hi);
            return EXIT_MESH;
        }
        m->V[i] = s;
    }
    return EXIT_OK;
}

int cli_unit_unscale(const char *cmd, const char *in, double *X, size_t n, int e)
{
    for (size_t i = 0; i < n; i++) {
        double s = ldexp(X[i], e);
        if (!isfinite(s)) {
            fprintf(stderr,
                    "scaf %s: %s: a result coordinate (%g x 2^%d) is beyond the largest double "
                    "(%g): the input is too close to it; scale it down\n",
                    cmd, in, X[i], e, DBL_MAX);
            return EXIT_MESH;
        }
        X[i] = s;
    }
    return EXIT_OK;
}
