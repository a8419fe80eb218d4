/* tools/cli_unit_scale: see cli_unit_scale.h; the scaling itself is
 * app/unit_scale, which the public 3D functions use too. */
#include "cli_unit_scale.h"

#include <stdio.h>

#include "app/unit_scale.h"
#include "exit_codes.h"

int cli_unit_scale(const char *cmd, const char *in, mesh *m, int *e)
{
    scaf_error err;
    err_clear(&err);
    if (unit_scale_down(m->nv, m->V, m->nf, m->F, e, &err) == SCAF_OK) return EXIT_OK;
    fprintf(stderr, "scaf %s: %s: %s\n", cmd, in, err.message);
    return EXIT_MESH;
}

int cli_unit_unscale(const char *cmd, const char *in, double *X, size_t n, int e)
{
    scaf_error err;
    err_clear(&err);
    if (unit_scale_up(X, n, e, &err) == SCAF_OK) return EXIT_OK;
    fprintf(stderr, "scaf %s: %s: %s\n", cmd, in, err.message);
    return EXIT_MESH;
}
