/* scaffold/tet_ops: the local operations of scaffold/tet_improve on a
 * tet_scaffold, each one applied only when it raises the worst quality of
 * the tets it replaces and every tet it makes is positively oriented
 * (exact orient3d), never across regions, protected faces or the hull.
 * The quality cache s->q of live tets must be current; every operation
 * keeps it so. Each returns 1 when applied, 0 when not (c->status says
 * whether an error stopped it).
 */
#ifndef SCAF_SCAFFOLD_TET_OPS_H
#define SCAF_SCAFFOLD_TET_OPS_H

#include "base/error.h"
#include "scaffold/tet_improve.h"
#include "scaffold/tet_scaffold.h"

typedef struct tet_ops {
    tet_scaffold *s;
    tet_improve_stats *st; /* op counts, tries */
    long long max_tries;   /* <= 0: no limit */
    scaf_status status;    /* the first hard error (memory, internal) */
    scaf_error *err;
} tet_ops;

/* 1 when the budget of tries is spent or an error happened. */
int tet_ops_exhausted(const tet_ops *c);

/* Remove the edge between corners i and j of tet t (3-2 flip when its ring
 * has 3 tets). */
int tet_ops_edge_removal(tet_ops *c, int t, int i, int j);

/* 2-3 flip of face f of tet t. */
int tet_ops_flip23(tet_ops *c, int t, int f);

/* Multi-face removal: the faces sandwiched between the apexes of the two
 * tets at face f of tet t (two or more, grown from face f) replaced by
 * the tets around the edge joining the apexes. */
int tet_ops_multi_face(tet_ops *c, int t, int f);

/* Move the free scaffold-only vertex v. */
int tet_ops_smooth(tet_ops *c, int v);

/* Remove the free scaffold-only vertex v, merging it into the neighbour
 * that leaves the best tets. */
int tet_ops_contract(tet_ops *c, int v);

/* Split the edge between corners i and j of tet t at its midpoint, then
 * move the new vertex. */
int tet_ops_split(tet_ops *c, int t, int i, int j);

/* Try the allowed operations (TET_OP_* mask) on tet t, in the order
 * edge removal, 2-3 flip, multi-face removal, smoothing, contraction,
 * split; 1 when one was
 * applied. */
int tet_ops_improve_tet(tet_ops *c, int t, unsigned ops);

#endif /* SCAF_SCAFFOLD_TET_OPS_H */
