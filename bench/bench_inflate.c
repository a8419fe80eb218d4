/* bench/bench_inflate: `scaf inflate` on a closed mesh (default
 * ../shared/data/closed/bunny.obj x30, 50 iterations): per-iteration
 * energy, step, tets, quality and seconds, then seconds per iteration,
 * the growth of the bounding-box diagonal, the bounding box against the
 * fixed box, and the exact checks (every tet positive at every iteration,
 * the surface free of self-intersections at the end).
 * usage: bench_inflate [FILE [K [ITERATIONS [LAMBDA_RATIO [newton|slim [OUT.obj]]]]]]
 * Environment: BOX_SCALE=S another box scale; IMPROVE=0 no improvement
 * pass, IMPROVE_TRIES / _GOAL / _PASSES its options. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/inflate.h"
#include "app/volume_deform.h"
#include "base/timer.h"
#include "geom/self_intersect.h"
#include "geom/tet_orient.h"
#include "mesh/mesh_io.h"

/* CPU seconds of this process (the machine is shared: wall time also
 * counts other jobs' turns) */
static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* positions of the scaffold's vertices: the surface's, then its own */
static int tets_positive(const volume_deform *vd)
{
    const scaffold_view *v = volume_deform_scaffold(vd);
    int n = v->nmesh + v->nextra;
    double *P = malloc(sizeof(double) * 3 * (size_t)n);
    if (!P) return 0;
    memcpy(P, volume_deform_positions(vd), sizeof(double) * 3 * (size_t)v->nmesh);
    memcpy(P + 3 * (size_t)v->nmesh, v->extra, sizeof(double) * 3 * (size_t)v->nextra);
    tet_orient_report r;
    int ok =
        tet_orient_check(n, P, v->n, v->simplices, &r, NULL) == SCAF_OK && r.positive == r.tets;
    free(P);
    return ok;
}

int main(int argc, char **argv)
{
    char def[1024];
    snprintf(def, sizeof def, "%s/closed/bunny.obj", SCAF_DATA_DIR);
    const char *path = argc > 1 ? argv[1] : def;
    double K = argc > 2 ? atof(argv[2]) : 30.0;
    int iters = argc > 3 ? atoi(argv[3]) : 50;
    volume_deform_options o = volume_deform_options_default();
    if (argc > 4) o.lambda_ratio = atof(argv[4]);
    if (argc > 5) o.solver = strcmp(argv[5], "slim") ? SCAF_SOLVER_NEWTON : SCAF_SOLVER_SLIM;
    if (getenv("BOX_SCALE")) o.box_scale = atof(getenv("BOX_SCALE"));
    if (getenv("IMPROVE_TRIES")) o.improve_opt.max_tries = atoll(getenv("IMPROVE_TRIES"));
    if (getenv("IMPROVE_GOAL")) o.improve_opt.quality_goal = atof(getenv("IMPROVE_GOAL"));
    if (getenv("IMPROVE_PASSES")) o.improve_opt.max_passes = atoi(getenv("IMPROVE_PASSES"));
    if (getenv("IMPROVE")) o.improve = atoi(getenv("IMPROVE"));
    scaf_set_threads(1); /* as `scaf inflate` */
    mesh m;
    mesh_read_info info;
    scaf_error e;
    if (mesh_read(path, &m, &info, &e) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", path, e.message);
        return 1;
    }
    double *target = malloc(sizeof(double) * 3 * (size_t)m.nv);
    inflate_target(m.nv, m.V, m.nf, m.F, K, target);
    double t0 = timer_now(), c0 = cpu_now();
    volume_deform vd;
    if (volume_deform_init(&vd, m.nv, m.V, m.nf, m.F, target, &o, &e) != SCAF_OK) {
        fprintf(stderr, "%s: %s\n", path, e.message);
        return 1;
    }
    double t_init = timer_now() - t0, c_init = cpu_now() - c0, t_iter = 0.0, c_iter = 0.0;
    double diag0 = inflate_bbox_diagonal(m.nv, m.V);
    int all_positive = 1;
    printf("| it | energy | step | tets | scaffold vertices | q min | q p5 | s |\n"
           "|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < iters; i++) {
        volume_deform_iteration it;
        double c1 = cpu_now();
        scaf_status st = volume_deform_step(&vd, &it, &e);
        c_iter += cpu_now() - c1;
        if (st != SCAF_OK) {
            fprintf(stderr, "iteration %d: %s\n", i + 1, e.message);
            return 1;
        }
        t_iter += it.seconds;
        all_positive = all_positive && tets_positive(&vd);
        printf("| %d | %.6g | %.3g | %d | %d | %.3g | %.3g | %.4f |\n", it.iteration, it.energy,
               it.step, it.tets, it.scaffold_vertices, it.quality_min, it.quality_p5, it.seconds);
    }
    const double *X = volume_deform_positions(&vd);
    const scaffold_view *v = volume_deform_scaffold(&vd);
    double box_diag = 0.0;
    for (int k = 0; k < 3; k++)
        box_diag += (v->box_hi[k] - v->box_lo[k]) * (v->box_hi[k] - v->box_lo[k]);
    box_diag = sqrt(box_diag);
    si_report r;
    si_check(m.nv, X, m.nf, m.F, &r, NULL);
    double diag = inflate_bbox_diagonal(m.nv, X);
    printf("\ninit (TetGen + first improvement) %.3f s (CPU %.3f s); %d iterations %.3f s, "
           "%.4f s/iteration (CPU %.4f s/iteration)\n",
           t_init, c_init, iters, t_iter, t_iter / iters, c_iter / iters);
    printf("bbox diagonal x%.3f (%.1f%% of the box diagonal, box/initial %.3f)\n", diag / diag0,
           100.0 * diag / box_diag, box_diag / diag0);
    printf("every tet positive at every iteration: %s; surface intersection-free: %s (%lld "
           "pairs)\n",
           all_positive ? "yes" : "NO", r.intersection_free ? "yes" : "NO", r.pairs);
    if (argc > 6) { /* write the surface */
        memcpy(m.V, X, sizeof(double) * 3 * (size_t)m.nv);
        mesh_write_obj(argv[6], &m, NULL);
    }
    volume_deform_free(&vd);
    free(target);
    mesh_free(&m);
    return all_positive && r.intersection_free ? 0 : 1;
}
