/* app/uv_fans: giving each fan of faces around a UV index its own index.
 *
 * In a mesh with UV seams, a chart may touch itself at a vertex: the faces
 * around one vt index then form several fans that are not linked through
 * edges (a pinch point of the cut surface: spot.obj, human_neutral.obj).
 * As a surface, the chart is a disk whose boundary passes that vertex
 * twice; to parametrize it, each fan gets its own UV index (the first fan
 * keeps the original one), so the chart becomes a disk (or a disk with
 * holes) in UV index space. Faces are linked across a UV edge used by
 * exactly two faces; UV edges with more faces link all of them (a truly
 * non-manifold edge stays non-manifold and the chart check rejects it).
 * Deterministic; fails only with SCAF_ERR_NOMEM.
 */
#ifndef SCAF_APP_UV_FANS_H
#define SCAF_APP_UV_FANS_H

#include "base/error.h"

/* nf, FT   #F by 3 UV indices in [0, nuv) (validated by the caller)
 * FT_out   #F by 3 out (may not alias FT)
 * nuv_out  out: the new UV count (>= nuv; new indices at the end)
 * orig     out, may be NULL: allocated (*nuv_out entries) original UV index
 *          of every new index (free with free) */
scaf_status uv_split_fans(int nf, const int *FT, int nuv, int *FT_out, int *nuv_out, int **orig,
                          scaf_error *err);

#endif /* SCAF_APP_UV_FANS_H */
