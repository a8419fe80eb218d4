/* tests/support/loop_valid: see loop_valid.h. */
#include "support/loop_valid.h"

#include "geom/bijectivity.h"
#include "geom/predicates.h"

int test_loop_state_valid(const scaf_loop *L)
{
    bij_report rep;
    if (bij_check(L->nv, L->uv, L->nf, L->F, NULL, NULL, &rep, NULL) != SCAF_OK || !rep.bijective)
        return 0;
    const scaffold_view *v = scaf_loop_scaffold_view(L);
    for (int s = 0; s < v->n; s++) {
        const double *p[3];
        for (int i = 0; i < 3; i++) {
            int id = v->simplices[3 * s + i];
            p[i] = id < v->nmesh ? L->uv + 2 * (size_t)id : v->extra + 2 * (size_t)(id - v->nmesh);
        }
        if (!(orient2d(p[0], p[1], p[2]) > 0)) return 0;
    }
    return 1;
}
