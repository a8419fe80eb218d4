/* mesh/uv_verdict: see uv_verdict.h. */
#include "mesh/uv_verdict.h"

scaf_status mesh_uv_verdict(const mesh *m, bij_report *rep, scaf_error *err)
{
    return bij_check(m->nuv, m->UV, m->nf, m->FT, NULL, NULL, rep, err);
}
