/* tests/support/param_watch: see param_watch.h. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "support/param_watch.h"

#include "app/param.h"
#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "support/support.h"

typedef struct watch {
    const scaf_param_t *p;
    int calls, not_bijective, energy_rises;
} watch;

static int every_iteration(const scaf_iteration_info_t *info, void *user)
{
    watch *w = user;
    const scaf_loop *L = param_loop(w->p);
    bij_report rep;
    scaf_error err;
    if (bij_check(L->nv, L->uv, L->nf, L->F, NULL, NULL, &rep, &err) != SCAF_OK || !rep.bijective ||
        rep.flipped || rep.degenerate || rep.boundary_crossings) {
        print_error("iteration %d: flipped %d degenerate %d crossings %lld\n", info->iteration,
                    rep.flipped, rep.degenerate, rep.boundary_crossings);
        w->not_bijective++;
    }
    if (info->step > 0 && !(info->total_after < info->total_before)) w->energy_rises++;
    w->calls++;
    return 0;
}

double param_run_watched(const char *rel, int iterations, scaf_init init, char *rejected,
                         size_t size)
{
    char buf[1024];
    const char *path = test_data_path(rel, buf, sizeof buf);
    if (!path) return NAN;
    mesh m;
    scaf_error err;
    assert_int_equal(mesh_read(path, &m, NULL, &err), SCAF_OK);
    scaf_options_t o = scaf_options_default();
    o.init = init;
    o.tolerance = 0;
    scaf_param_t *p = scaf_param_new(&o);
    assert_non_null(p);
    scaf_status st = mesh_has_uv(&m)
        ? scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT)
        : scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL);
    if (st == SCAF_ERR_MESH && rejected) {
        snprintf(rejected, size, "%s", scaf_param_error(p));
        scaf_param_destroy(p);
        mesh_free(&m);
        return NAN;
    }
    if (st != SCAF_OK) print_error("%s: %s\n", rel, scaf_param_error(p));
    assert_int_equal(st, SCAF_OK);
    double e0 = scaf_param_energy(p);
    watch w = {p, 0, 0, 0};
    st = scaf_param_run(p, iterations, every_iteration, &w);
    if (st != SCAF_OK) print_error("%s: %s\n", rel, scaf_param_error(p));
    assert_int_equal(st, SCAF_OK);
    assert_int_equal(w.calls, iterations);
    assert_int_equal(w.not_bijective, 0);
    assert_int_equal(w.energy_rises, 0);
    double e1 = scaf_param_energy(p);
    print_message("%s: %d charts, E %.6g -> %.6f after %d iterations\n", rel,
                  scaf_param_chart_count(p), e0, e1, w.calls);
    assert_true(e1 < e0);
    scaf_param_destroy(p);
    mesh_free(&m);
    return e1;
}
