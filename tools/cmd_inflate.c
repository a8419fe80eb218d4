/* tools/cmd_inflate: `scaf inflate IN -o OUT.obj --scale K`, a closed
 * surface grown toward K times its size inside a fixed box of tets,
 * never passing through itself or the box (scaf_inflate of the public
 * scaf/volume.h: the 3D SCAF loop; the paper's Figure 10).
 *
 * The target is the surface scaled K times about its area-weighted
 * centroid; each of the N iterations pulls the surface
 * toward it (spokes-and-rims ARAP) as far as the scaffold allows, and
 * every tet stays positively oriented (exact), so the surface stays free
 * of self-intersections. Writes the input's vertices and faces at the new
 * positions; --tets the final tet mesh (MEDIT .mesh, label 1 inside the
 * surface, 2 outside); --report the iterations; --png the input and the
 * result side by side (app/surface_render). Exit status: 0 written,
 * 2 usage, 3 input unreadable, 4 not a closed manifold surface free of
 * self-intersections (nothing to mesh), 5 output not written, 6 numerical
 * failure, 7 out of memory, 8 interrupted.
 */
#include <math.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/json_write.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_progress.h"
#include "cli_signal.h"
#include "cli_surface_png.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "mesh/tet_medit.h"
#include "scaf/volume.h"

#define INFLATE_MAX_ITERATIONS 100000

static void about(FILE *out)
{
    fputs("Grow the closed surface IN toward K times its size (scaled about its centroid)\n"
          "inside a fixed box around it: the 3D SCAF loop, with tetrahedra filling the box\n"
          "inside and outside the surface. The surface presses against the box and against\n"
          "itself but never passes through either: every tet stays positively oriented\n"
          "(checked exactly) at every iteration. Writes the input's vertices and faces at\n"
          "the new positions. IN must be a closed manifold triangle surface free of\n"
          "self-intersections.\n"
          "\n",
          out);
}

static void after(FILE *out)
{
    fputs(CLI_OUTPUTS_HELP "\n", out);
    exit_codes_print(out);
}

/* One iteration's numbers, as the progress callback gave them. */
typedef struct inflate_iteration {
    int iteration;
    double energy, step;
    int tets, scaffold_vertices;
    double quality_min, quality_p5, seconds;
} inflate_iteration;

typedef struct inflate_log {
    int n; /* iterations done */
    inflate_iteration *it;
    double diag0, diag1, box_lo[3], box_hi[3];
} inflate_log;

static scaf_status write_report(const char *path, const char *in, double K, const inflate_log *g,
                                scaf_error *err)
{
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = a.f;
    json_write_report_head(o, "inflate");
    fputs(",\n  \"input\": ", o);
    json_write_string(o, in);
    fputs(",\n  \"scale\": ", o);
    json_write_number(o, K);
    fprintf(o, ",\n  \"iteration_count\": %d,\n  \"box_lo\": [", g->n);
    for (int k = 0; k < 3; k++) {
        if (k) fputs(", ", o);
        json_write_number(o, g->box_lo[k]);
    }
    fputs("],\n  \"box_hi\": [", o);
    for (int k = 0; k < 3; k++) {
        if (k) fputs(", ", o);
        json_write_number(o, g->box_hi[k]);
    }
    fputs("],\n  \"bbox_diagonal_before\": ", o);
    json_write_number(o, g->diag0);
    fputs(",\n  \"bbox_diagonal_after\": ", o);
    json_write_number(o, g->diag1);
    fputs(",\n  \"iterations\": [", o);
    for (int i = 0; i < g->n; i++) {
        const inflate_iteration *r = &g->it[i];
        fprintf(o, "%s\n    {\"iteration\": %d, \"energy\": ", i ? "," : "", r->iteration);
        json_write_number(o, r->energy);
        fputs(", \"step\": ", o);
        json_write_number(o, r->step);
        fprintf(o, ", \"tets\": %d, \"scaffold_vertices\": %d, \"quality_min\": ", r->tets,
                r->scaffold_vertices);
        json_write_number(o, r->quality_min);
        fputs(", \"quality_p5\": ", o);
        json_write_number(o, r->quality_p5);
        fputs(", \"seconds\": ", o);
        json_write_number(o, r->seconds);
        fputc('}', o);
    }
    fputs("\n  ]\n}\n", o);
    return atomic_commit(&a, err);
}

typedef struct inflate_watch {
    int quiet;
    inflate_log *g;
    cli_progress bar;
} inflate_watch;

static int on_iteration(const scaf_volume_step_info_t *e, void *user)
{
    inflate_watch *w = user;
    inflate_iteration *r = &w->g->it[w->g->n++];
    *r = (inflate_iteration){
        e->step,        e->energy,     e->step_length, e->tets, e->scaffold_vertices,
        e->quality_min, e->quality_p5, e->seconds};
    char extra[64];
    snprintf(extra, sizeof extra, "quality min %.3g", r->quality_min);
    cli_progress_step(&w->bar, r->iteration, r->energy, NAN, extra);
    if (!w->quiet && !cli_progress_live(&w->bar))
        fprintf(stderr,
                "scaf inflate: iteration %d: energy %.6g, step %.3g, %d tets, quality min "
                "%.3g p5 %.3g, %.3f s\n",
                r->iteration, r->energy, r->step, r->tets, r->quality_min, r->quality_p5,
                r->seconds);
    cli_signal_test_point(e->step);
    return cli_signal_caught() != 0;
}

/* Run scaf_inflate on m->V (updated) into h. 0, or the exit status after
 * printing why. */
static int run_inflate(const char *in, mesh *m, const scaf_inflate_options_t *o, int quiet,
                       inflate_log *g, scaf_volume_t *h)
{
    inflate_watch w = {quiet, g, {0}};
    cli_progress_init(&w.bar, "inflate", quiet);
    cli_progress_phase(&w.bar, "inflate", o->iterations, 1, 0.0);
    scaf_status st = scaf_inflate(h, m->V, m->nv, m->F, m->nf, o, on_iteration, &w);
    cli_progress_done(&w.bar, NULL);
    if (st == SCAF_ERR_CANCELLED && cli_signal_caught())
        return EXIT_OK; /* reported by the caller */
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf inflate: %s: %s\n", in, scaf_volume_error(h));
        return exit_code_for(st);
    }
    scaf_volume_summary_t s = {.struct_size = sizeof s};
    scaf_volume_get_summary(h, &s);
    scaf_volume_get_positions(h, m->V);
    for (int k = 0; k < 3; k++) {
        g->box_lo[k] = s.box_lo[k];
        g->box_hi[k] = s.box_hi[k];
    }
    g->diag0 = s.diagonal_before;
    g->diag1 = s.diagonal_after;
    if (!quiet)
        fprintf(stderr, "scaf inflate: bounding-box diagonal x%.4g after %d iterations\n",
                g->diag0 > 0 ? g->diag1 / g->diag0 : 0.0, g->n);
    return EXIT_OK;
}

/* The final tets: surface vertices at the result, then the scaffold's own. */
static scaf_status write_tets(const char *path, const scaf_volume_t *h, scaf_error *err)
{
    int np = scaf_volume_tet_vertex_count(h), nt = scaf_volume_tet_count(h);
    double *P = malloc(sizeof(double) * 3 * (size_t)(np > 0 ? np : 1));
    int *T = malloc(sizeof(int) * 4 * (size_t)(nt > 0 ? nt : 1));
    int *label = malloc(sizeof(int) * (size_t)(nt > 0 ? nt : 1));
    scaf_status st = P && T && label ? SCAF_OK : err_nomem(err, "tet output");
    if (st == SCAF_OK) st = scaf_volume_get_tets(h, P, T, label);
    if (st == SCAF_OK) st = tet_medit_write(path, np, P, nt, T, label, err);
    free(P);
    free(T);
    free(label);
    return st;
}

static int inflate_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *report = NULL, *tets = NULL;
    double K = 0.0;
    int iterations = 50, quiet = 0, threads = 1;
    scaf_inflate_options_t o = scaf_inflate_options_default();
    cli_surface_png png;
    cli_surface_png_init(&png);
    static const char *const solvers[] = {"slim", "newton", NULL};
    static const int solver_values[] = {SCAF_SOLVER_SLIM, SCAF_SOLVER_NEWTON};
    int solver = (int)o.solver, deterministic = 0;
    char box_help[160];
    snprintf(box_help, sizeof box_help,
             "the box: the bounding box scaled S times about its centre, > 1 (default %g)",
             o.box_scale);
    const cli_option options[] = {
        CLI_STRING("output", 'o', &out, "FILE", "the OBJ to write (nothing is left on failure)"),
        CLI_DOUBLE("scale", 'k', &K, "K", 0, 1e6, "the target's size factor, > 0 (< 1 shrinks)",
                   .open_min = 1),
        CLI_INT("iterations", 'n', &iterations, "N", 1, INFLATE_MAX_ITERATIONS,
                "iterations, 1..100000 (default 50)"),
        CLI_INT("threads", 0, &threads, "N", 1, INT_MAX,
                "threads of the per-tet work and of the factorization (default 1)"),
        CLI_FLAG("deterministic", 0, &deterministic, "the same bytes for any --threads N (slower)"),
        CLI_STRING("tets", 0, &tets, "FILE",
                   "also write the final tets (MEDIT .mesh; label 1 inside the surface, 2 "
                   "outside)"),
        CLI_STRING("report", 0, &report, "FILE",
                   "a JSON report: the box, the bounding-box diagonal before and after, and per "
                   "iteration the surface energy, step, scaffold tets and vertices, tet quality "
                   "(minimum and 5th percentile of 6 sqrt(2) V / l_rms^3) and seconds"),
        CLI_SURFACE_PNG_OPTIONS(&png, "the input and the inflated surface side by side"),
        CLI_DOUBLE("box-scale", 0, &o.box_scale, "S", 1, 1e6, box_help, .open_min = 1),
        CLI_ENUM("solver", 0, &solver, "NAME", solvers,
                 "newton (default: projected Newton, falls back to SLIM when its step fails) or "
                 "slim",
                 .values = solver_values),
        CLI_FLAG("quiet", 'q', &quiet, "no per-iteration lines on stderr"),
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "inflate",
                                     .usage = "usage: scaf inflate IN -o OUT.obj --scale K "
                                              "[--iterations N] [--tets OUT.mesh]\n"
                                              "                    [--report R.json] [--png P.png "
                                              "[--png-size N]] [--box-scale S]\n"
                                              "                    [--solver slim|newton] "
                                              "[--threads N] [--deterministic] "
                                              "[--quiet]\n\n",
                                     .about = about,
                                     .after = after,
                                     .options = options,
                                     .help_column = 21,
                                     .positionals = &in,
                                     .max_positionals = 1,
                                     .positional_name = "input"};
    int parsed = cli_options_parse(&cmd, argc, argv);
    if (parsed != CLI_OPTIONS_OK) return cli_options_done(&cmd, parsed);
    o.solver = (scaf_solver)solver;
    if (deterministic) scaf_set_deterministic(1);
    if (!in || !out || !(K > 0)) {
        fprintf(stderr, "scaf inflate: %s (see --help)\n",
                !in        ? "missing the input surface"
                    : !out ? "missing -o OUT.obj"
                           : "missing --scale K");
        return EXIT_USAGE;
    }
    if (cli_surface_png_finish("inflate", &png) < 0) return EXIT_USAGE;
    cli_outputs outs;
    cli_outputs_init(&outs, "inflate", in);
    int k = cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
    int kt = cli_outputs_add(&outs, "--tets", tets, CLI_OUTPUT_FILE);
    int kr = cli_outputs_add(&outs, "--report", report, CLI_OUTPUT_FILE);
    int kp = cli_outputs_add(&outs, "--png", png.path, CLI_OUTPUT_FILE);
    int rc = cli_outputs_check(&outs);
    if (rc != EXIT_OK) return rc;
    /* one thread unless asked: the 3D systems are small next to their
     * assembly and line search, and idle OpenBLAS threads spin (bunny x30:
     * 12% of the time in sched_yield with two) */
    scaf_set_threads(threads);
    mesh m;
    mesh_read_info info;
    if ((rc = cli_read_mesh("inflate", in, quiet, &m, &info)) != EXIT_OK) return rc;
    inflate_log g;
    memset(&g, 0, sizeof g);
    g.it = malloc(sizeof *g.it * (size_t)iterations);
    double *start = kp >= 0 ? malloc(sizeof(double) * 3 * (size_t)(m.nv > 0 ? m.nv : 1)) : NULL;
    if (start) memcpy(start, m.V, sizeof(double) * 3 * (size_t)m.nv);
    scaf_volume_t *h = scaf_volume_new();
    if (!g.it || (kp >= 0 && !start) || !h) {
        fprintf(stderr, "scaf inflate: out of memory\n");
        rc = EXIT_NOMEM;
    } else {
        o.scale = K;
        o.iterations = iterations;
        rc = run_inflate(in, &m, &o, quiet, &g, h);
    }
    if (rc == EXIT_OK && cli_signal_report("inflate")) rc = EXIT_CANCELLED;
    if (rc == EXIT_OK) {
        scaf_error err;
        err_clear(&err);
        const char *path = cli_outputs_begin(&outs, k, &err);
        rc = cli_outputs_end(&outs, k, path ? mesh_write_obj(path, &m, &err) : SCAF_ERR_IO, &err);
        if (rc == EXIT_OK && kt >= 0) {
            path = cli_outputs_begin(&outs, kt, &err);
            rc = cli_outputs_end(&outs, kt, path ? write_tets(path, h, &err) : SCAF_ERR_IO, &err);
        }
        if (rc == EXIT_OK && kr >= 0) {
            path = cli_outputs_begin(&outs, kr, &err);
            rc = cli_outputs_end(&outs, kr,
                                 path ? write_report(path, in, K, &g, &err) : SCAF_ERR_IO, &err);
        }
        surface_view panels[2] = {{m.nv, start, m.nf, m.F, NULL, 0, NULL, "input"},
                                  {m.nv, m.V, m.nf, m.F, NULL, 0, NULL, "inflated"}};
        if (rc == EXIT_OK) rc = cli_surface_png_write(&outs, kp, 2, panels, &png);
        if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    }
    cli_outputs_abort(&outs);
    free(start);
    scaf_volume_destroy(h);
    free(g.it);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_inflate(int argc, char **argv) { return cli_signal_run(inflate_main, argc, argv); }
