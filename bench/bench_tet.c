/* bench/bench_tet: the exact 3D self-intersection check and the initial
 * tetrahedral scaffold (TetGen in a 3x box of 8 x 8 squares per side, plus
 * the exact output checks) on the closed meshes of ../shared/data (read
 * time excluded) and on generated icospheres. Best of 3, as Markdown. */
#include <stdio.h>
#include <string.h>

#include "base/timer.h"
#include "geom/self_intersect.h"
#include "geom/tet_box_mesh.h"
#include "mesh/mesh_io.h"
#include "mesh/samples.h"

static void run(const char *name, const mesh *m)
{
    double best_check = 1e30, best_tet = 1e30;
    si_report r;
    tet_box_mesh tm;
    memset(&tm, 0, sizeof tm);
    scaf_error e;
    scaf_status s = SCAF_OK;
    for (int rep = 0; rep < 3; rep++) {
        double t0 = timer_now();
        si_check(m->nv, m->V, m->nf, m->F, &r, NULL);
        double t1 = timer_now();
        if (t1 - t0 < best_check) best_check = t1 - t0;
        double lo[3], hi[3];
        tet_box_around(m->nv, m->V, 3, lo, hi);
        tet_box_mesh_free(&tm);
        s = tet_box_mesh_build(m->nv, m->V, m->nf, m->F, lo, hi, 8, &tm, &e);
        double t2 = timer_now();
        if (t2 - t1 < best_tet) best_tet = t2 - t1;
    }
    if (s == SCAF_OK)
        printf("| %s | %d | %lld | %.3f | %d | %d | %d | %.3f |\n", name, m->nf, r.pairs,
               best_check, tm.nv, tm.nt, tm.ninside, best_tet);
    else
        printf("| %s | %d | %lld | %.3f | refused: %s | | | |\n", name, m->nf, r.pairs, best_check,
               e.message);
    tet_box_mesh_free(&tm);
}

int main(void)
{
    printf("| mesh | faces | intersecting pairs | check s | scaffold vertices | tets | tets inside "
           "| "
           "TetGen + checks s |\n|---|---|---|---|---|---|---|---|\n");
    static const char *files[] = {"bunny.obj",     "leg-intersect.off",    "leg-flow6.off",
                                  "fertility.off", "nefertiti-lowres.obj", "armadillo.obj"};
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/closed/%s", SCAF_DATA_DIR, files[i]);
        mesh m;
        mesh_read_info info;
        if (mesh_read(path, &m, &info, NULL) != SCAF_OK) continue;
        run(files[i], &m);
        mesh_free(&m);
    }
    for (int n = 10; n <= 40; n += 30) {
        mesh m;
        char name[64];
        snprintf(name, sizeof name, "icosphere %d", n);
        if (mesh_sample_make("icosphere", n, &m, NULL) != SCAF_OK) continue;
        run(name, &m);
        mesh_free(&m);
    }
    return 0;
}
