/* app/area_matched_api: scaf_area_matched_energy, the public entry to
 * opt/area_matched_energy with its arguments checked (see scaf.h). */
#include <math.h>
#include <stddef.h>

#include "opt/area_matched_energy.h"
#include "scaf/scaf.h"

static int indices_ok(const int *I, int n, int bound)
{
    for (int k = 0; k < 3 * n; k++)
        if (I[k] < 0 || I[k] >= bound) return 0;
    return 1;
}

scaf_status scaf_area_matched_energy(const double *V, int nv, const int *F, int nf,
                                     const double *UV, int nuv, const int *FT, double *E)
{
    if (!V || !F || !UV || !E || nv < 1 || nf < 1) return SCAF_ERR_USAGE;
    if (!FT) FT = F, nuv = nv;
    if (nuv < 1 || !indices_ok(F, nf, nv) || !indices_ok(FT, nf, nuv)) return SCAF_ERR_USAGE;
    double e = area_matched_energy(V, F, nf, UV, FT);
    if (isnan(e)) return SCAF_ERR_MESH;
    *E = e;
    return SCAF_OK;
}
