/* scaffold/scaffold_provider: what the SCAF loop needs from a scaffold.
 *
 * A scaffold fills the space between the mesh and a box around it with
 * simplices of the mesh's dimension d (triangles for d = 2, tetrahedra for
 * d = 3), sharing the mesh's boundary vertices. The loop asks a provider,
 * at each iteration:
 *   refresh  make the scaffold fit the current mesh positions X (nmesh by
 *            d): the first call builds it, later calls may build it again
 *            (2D: a new constrained Delaunay triangulation) or repair the
 *            last one (3D: flips, smoothing of scaffold vertices), and may
 *            move scaffold-only vertices. Every simplex must be positively
 *            oriented at X. On failure the scaffold is empty (view: n = 0)
 *            and err says why;
 *   view     the current scaffold (valid until the next refresh):
 *              simplices  n by d+1 vertex ids, positively oriented; an id
 *                         below nmesh is a mesh vertex, id nmesh + i the
 *                         scaffold-only vertex i;
 *              extra      nextra by d positions of the scaffold-only
 *                         vertices; the loop writes the accepted step's
 *                         positions back here (pictures, 3D repair);
 *              extra_fixed nextra flags: 1 = held fixed in the solve (the
 *                         box), 0 = free;
 *              eps        the rest-volume guard: a scaffold simplex smaller
 *                         than eps gets a regular rest shape of volume eps
 *                         (paper, 2D: l^2 / 4, l the shortest boundary edge;
 *                         2D blends towards it from 2 eps down to eps / 4,
 *                         opt/simplices);
 *              box_lo/hi  the box (first d entries);
 *   destroy  free everything.
 * The scaffold's options (scaffold_options: box scale, box shape, points
 * per box side, quality bound) are passed to each refresh, so a caller may
 * change them between iterations; a provider ignores what does not apply
 * to it. Implementations: scaffold/scaffold_cdt (2D).
 */
#ifndef SCAF_SCAFFOLD_SCAFFOLD_PROVIDER_H
#define SCAF_SCAFFOLD_SCAFFOLD_PROVIDER_H

#include "base/error.h"
#include "scaffold/scaffold_build.h"

typedef struct scaffold_view {
    int d;                            /* 2 or 3 */
    int nmesh;                        /* ids < nmesh are mesh vertices */
    int n;                            /* simplices */
    const int *simplices;             /* n by d+1 */
    int nextra;                       /* scaffold-only vertices */
    double *extra;                    /* nextra by d */
    const unsigned char *extra_fixed; /* nextra */
    double eps;
    double box_lo[3], box_hi[3];
} scaffold_view;

typedef struct scaffold_provider scaffold_provider;

typedef struct scaffold_provider_ops {
    scaf_status (*refresh)(scaffold_provider *p, const double *X, const scaffold_options *o,
                           scaf_error *err);
    void (*view)(const scaffold_provider *p, scaffold_view *v);
    void (*destroy)(scaffold_provider *p);
} scaffold_provider_ops;

/* Implementations embed this as their first member. */
struct scaffold_provider {
    const scaffold_provider_ops *ops;
    int d;     /* dimension */
    int nmesh; /* mesh vertices */
};

/* Destroy p (safe on NULL). */
static inline void scaffold_provider_destroy(scaffold_provider *p)
{
    if (p) p->ops->destroy(p);
}

#endif /* SCAF_SCAFFOLD_SCAFFOLD_PROVIDER_H */
