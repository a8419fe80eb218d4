/* opt/split_symbolic: the symbolic factor of a system whose leading part
 * keeps its pattern and its order while the rest changes, without
 * analysing the leading part again.
 *
 * SCAF's systems are [mesh | scaffold]: the mesh block's pattern never
 * changes, its vertices keep one fill-reducing order, and the scaffold
 * (re-triangulated every iteration) is ordered after it. With the fixed
 * vertices eliminated first, their part of the factor is the fixed block's
 * own factor plus, in each column, the variable rows reachable from its
 * subtree: a variable vertex coupled to a fixed one appears in the
 * supernodes on the path from that vertex's supernode to its root, and
 * the variable block receives, as fill, a clique on the variable vertices
 * reaching each root. So the fixed block is analysed once (CHOLMOD, on
 * creation); each new pattern costs walks up the fixed supernodal tree,
 * the (small) analysis of the variable block with that clique, and
 * copying the fixed rows into the new factor -- no pass of CHOLMOD's over
 * the fixed block. The fixed supernodes stay those of the fixed block
 * alone (CHOLMOD's amalgamation, which would also weigh the variable rows,
 * may merge slightly differently: the same factorization up to the order
 * of its sums).
 *
 * Works on vertex graphs (opt/block_symbolic expands to unknowns). Kept
 * apart from cholmod_solver.h: only CHOLMOD-facing code includes it. */
#ifndef SCAF_OPT_SPLIT_SYMBOLIC_H
#define SCAF_OPT_SPLIT_SYMBOLIC_H

#include <cholmod.h>

typedef struct opt_split_symbolic opt_split_symbolic;

/* The fixed part: the first nf vertices of the graph cp / ri (upper
 * pattern, columns sorted: columns 0..nf-1 then hold only fixed rows),
 * eliminated in the order fperm (nf entries, a permutation of 0..nf-1;
 * the etree's postorder is applied on top, as CHOLMOD does). Analyses the
 * fixed block with cm's relaxation. NULL with cm->status set on failure
 * (status OK: fperm is not a permutation). */
opt_split_symbolic *opt_split_create(cholmod_common *cm, int nf, const int *cp, const int *ri,
                                     const int *fperm);

void opt_split_destroy(opt_split_symbolic *S);

/* Whether S was made for these nf fixed vertices in this order, with this
 * fixed pattern (the first nf columns of cp / ri). pattern_known: the
 * caller knows that pattern to be S's (it compared it already), so only
 * nf and the order are compared. */
int opt_split_matches(const opt_split_symbolic *S, int nf, const int *cp, const int *ri,
                      const int *fperm, int pattern_known);

/* The supernodal symbolic factor (pattern, LL') of the whole graph of nv
 * vertices (cp / ri as for opt_split_create, same fixed part): the fixed
 * vertices first in S's order, the others after them in the order the
 * analysis of their block gives (natural order, then postorder). NULL
 * with cm->status set on failure. */
cholmod_factor *opt_split_factor(const opt_split_symbolic *S, cholmod_common *cm, int nv,
                                 const int *cp, const int *ri);

#endif /* SCAF_OPT_SPLIT_SYMBOLIC_H */
