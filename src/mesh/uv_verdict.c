/* mesh/uv_verdict: see uv_verdict.h. */
#include "mesh/uv_verdict.h"

#include <stdlib.h>

scaf_status mesh_uv_verdict(const mesh *m, bij_report *rep, scaf_error *err)
{
    return bij_check(m->nuv, m->UV, m->nf, m->FT, NULL, NULL, rep, err);
}

scaf_status mesh_uv_verdict_gltf(const mesh *m, bij_report *rep, scaf_error *err)
{
    double *R = malloc(sizeof(double) * 2 * (size_t)(m->nuv ? m->nuv : 1));
    if (!R) return err_nomem(err, "rounded UVs");
    for (size_t i = 0; i < (size_t)m->nuv; i++) {
        R[2 * i] = (double)(float)m->UV[2 * i];
        R[2 * i + 1] = 1.0 - (double)(float)(1.0 - m->UV[2 * i + 1]); /* exact in double */
    }
    scaf_status st = bij_check(m->nuv, R, m->nf, m->FT, NULL, NULL, rep, err);
    free(R);
    return st;
}
