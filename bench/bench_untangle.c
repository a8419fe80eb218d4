/* bench/bench_untangle: `scaf untangle` on a closed self-intersecting
 * mesh (default ../shared/data/closed/leg-intersect.off): per flow step
 * and iteration the distance to the input and the CPU seconds (this
 * process's: the machine is shared, wall time also counts other jobs'
 * turns), then the flow-back's CPU seconds per iteration, the final
 * distances and the exact check of the result.
 * usage: bench_untangle [FILE [ITERATIONS [newton|slim [ANCHOR]]]]
 * Environment: IMPROVE=0|1 the scaffold improvement pass off/on,
 * IMPROVE_TRIES / IMPROVE_OPS (tet_improve's TET_OP_* mask) its options;
 * VERIFY=1 the exact check after every iteration (not timed by the loop). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/untangle.h"
#include "geom/self_intersect.h"
#include "mesh/mesh_io.h"

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct clock_state {
    double last, back_cpu;
    int back;
} clock_state;

static int on_event(const untangle_event *e, void *user)
{
    clock_state *c = user;
    double now = cpu_now(), cpu = now - c->last;
    c->last = now;
    if (e->phase == UNTANGLE_FLOW) {
        printf("flow %3d  pairs %5lld  rms %.5f  max %.4f  cpu %.3f s\n", e->step, e->pairs, e->rms,
               e->max, cpu);
    } else {
        c->back_cpu += cpu;
        c->back++;
        printf("iter %3d  energy %.5f  arap %.5f  rms %.5f  max %.4f  tets %d  qmin %.2g  cpu "
               "%.3f s  wall %.3f s\n",
               e->step, e->energy, e->arap, e->rms, e->max, e->tets, e->quality, cpu, e->seconds);
    }
    fflush(stdout);
    c->last = cpu_now(); /* the printing is not the run's */
    return 0;
}

int main(int argc, char **argv)
{
    char def[1024];
    snprintf(def, sizeof def, "%s/closed/leg-intersect.off", SCAF_DATA_DIR);
    const char *path = argc > 1 ? argv[1] : def;
    untangle_options o = untangle_options_default();
    if (argc > 2) o.iterations = atoi(argv[2]);
    if (argc > 3) o.deform.solver = strcmp(argv[3], "slim") ? SCAF_SOLVER_NEWTON : SCAF_SOLVER_SLIM;
    if (argc > 4) o.anchor_ratio = atof(argv[4]);
    if (getenv("IMPROVE")) o.deform.improve = atoi(getenv("IMPROVE"));
    if (getenv("IMPROVE_TRIES")) o.deform.improve_opt.max_tries = atoll(getenv("IMPROVE_TRIES"));
    if (getenv("IMPROVE_OPS")) o.deform.improve_opt.ops = (unsigned)atoi(getenv("IMPROVE_OPS"));
    if (getenv("VERIFY")) o.verify = atoi(getenv("VERIFY"));
    mesh m;
    mesh_read_info info;
    scaf_error err;
    if (mesh_read(path, &m, &info, &err) != SCAF_OK) {
        fprintf(stderr, "bench_untangle: %s\n", err.message);
        return 1;
    }
    printf("%s: %d vertices, %d faces; solver %s, improve %d, anchor %g\n", path, m.nv, m.nf,
           o.deform.solver == SCAF_SOLVER_SLIM ? "slim" : "newton", o.deform.improve,
           o.anchor_ratio);
    clock_state c = {cpu_now(), 0.0, 0};
    double t0 = c.last;
    untangle_result r;
    if (untangle_run(m.nv, m.V, m.nf, m.F, &o, on_event, &c, &r, &err) != SCAF_OK) {
        fprintf(stderr, "bench_untangle: %s\n", err.message);
        mesh_free(&m);
        return 1;
    }
    si_report rep;
    int free_ok = si_check(m.nv, r.X, m.nf, m.F, &rep, NULL) == SCAF_OK && rep.intersection_free;
    printf("flow steps %d, flowed rms %.5f max %.4f; %d iterations (%s, best %d): rms %.5f max "
           "%.4f (%.3f of the flowed); %.3f s CPU per iteration; total CPU %.2f s; result %s\n",
           r.flow_steps, r.flowed_rms, r.flowed_max, r.iterations, untangle_stop_name(r.stop),
           r.best_iteration, r.rms, r.max, r.rms / r.flowed_rms, c.back ? c.back_cpu / c.back : 0.0,
           cpu_now() - t0, free_ok ? "intersection-free" : "INTERSECTING");
    untangle_result_free(&r);
    mesh_free(&m);
    return free_ok ? 0 : 1;
}
