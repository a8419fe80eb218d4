/* tools/cmd_deform: `scaf deform IN.obj --targets T.json -o OUT.obj`:
 * planar deformation with soft handles, bijective at every iteration.
 *
 * A thin layer over app/deform: reads the planar mesh (z = 0, or its `vt`
 * when present) and the handle file (tools/deform_targets), runs the SCAF
 * loop with the handles as soft constraints, and writes the deformed mesh
 * as OBJ with the positions both as `v` (z = 0) and `vt`, so `scaf check`
 * verifies it; optionally a JSON report and SVG / PNG pictures. Bad input
 * gives a message and the exit status of tools/exit_codes.h, and no file.
 */
#include <math.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/deform.h"
#include "app/stop_reason.h"
#include "app/uv_svg.h"
#include "base/json_write.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_progress.h"
#include "cli_png.h"
#include "cli_signal.h"
#include "cli_uv_job.h"
#include "deform_targets.h"
#include "exit_codes.h"
#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"
#include "opt/handle_term.h"
#include "scaf/scaf.h"

static void about(FILE *o)
{
    fprintf(o,
            "Deforms a planar triangle mesh so that chosen vertices (handles) move towards\n"
            "target positions, with low distortion, inside a box of scaffold triangles that\n"
            "SCAF re-meshes every iteration: no triangle ever flips and the shape never\n"
            "overlaps itself, whatever the targets (handles get as close as that allows).\n"
            "\n"
            "IN: a planar mesh: its `vt` when it has UVs (handle vertices are then `vt`\n"
            "indices), else its `v` with z = 0. Every triangle counter-clockwise; the rest\n"
            "shape (zero distortion) is the input.\n"
            "T.json: {\"handles\": [{\"vertex\": 0, \"target\": [x, y]}, ...], \"weight\": W}\n"
            "with 0-based vertex indices; \"weight\" is optional (see --weight). A handle\n"
            "may have \"path\": [[x, y], ...], waypoints visited before its target (a drag:\n"
            "--frame-iterations each; every handle's path has the same length). One handle\n"
            "per vertex; every target and waypoint within 1e6 mesh sizes of the mesh\n"
            "(otherwise exit 4 naming the handle).\n"
            "Hard constraints: a handle with \"hard\": true (or every handle, --hard) must\n"
            "end exactly on its target: it pulls with the soft weight until its vertex can\n"
            "be placed exactly there without flipping a triangle (decided exactly, also\n"
            "against the scaffold, so the map stays bijective), then it is pinned. A\n"
            "top-level \"pins\": [i, ...] holds vertices where they are: a pinned vertex\n"
            "never moves, its coordinates stay the same bits through every iteration.\n"
            "When the pins and hard targets flip a triangle whose three corners they all\n"
            "hold, no bijective map exists: exit 9 before any work, naming the triangle.\n"
            "Hard targets still missing when the run stalls (%d iterations without one\n"
            "reached and without their error shrinking), stops or hits --iterations: exit\n"
            "9 naming how many; nothing is written.\n"
            "OUT: OBJ with the deformed positions as `v` (z = 0) and as `vt`.\n"
            "\n"
            "\n",
            deform_options_default().stall_iterations);
}

static void after(FILE *o)
{
    fputs(CLI_OUTPUTS_HELP "\n", o);
    exit_codes_print(o);
}

typedef struct deform_args {
    const char *in, *out, *targets, *report, *svg;
    int iterations, frame_iterations, no_remesh, verify, quiet, hard;
    int threads; /* --threads N; 0: one */
    double weight;
    int weight_given;
    cli_png png;
} deform_args;

static int parse_args(int argc, char **argv, deform_args *o)
{
    memset(o, 0, sizeof *o);
    o->iterations = 100;
    o->frame_iterations = 4;
    o->weight = NAN; /* not given */
    cli_png_init(&o->png, 0);
    int deterministic = 0;
    const cli_option options[] = {
        CLI_GROUP("options:"),
        CLI_STRING("output", 'o', &o->out, "FILE", "output OBJ (required)"),
        CLI_STRING("targets", 0, &o->targets, "FILE", "the handle file (required)"),
        CLI_INT("iterations", 0, &o->iterations, "N", 0, 100000000, "iteration cap (default 100)"),
        CLI_INT("frame-iterations", 0, &o->frame_iterations, "N", 1, INT_MAX,
                "iterations per waypoint of a drag (default 4)"),
        CLI_DOUBLE("weight", 0, &o->weight, "R", 0, INFINITY,
                   "handle weight ratio, dimensionless (default 10000; the file's \"weight\" "
                   "when given): w = R / #handles per squared distance, against the distortion "
                   "energy (an area): scale-free"),
        CLI_FLAG("hard", 0, &o->hard, "every handle's target is hard (see above)"),
        CLI_FLAG("no-remesh", 0, &o->no_remesh,
                 "keep the first scaffold's connectivity (the paper's Figure 4 baseline: the "
                 "deformation locks)"),
        CLI_FLAG("verify", 0, &o->verify, "check bijectivity exactly after every iteration"),
        CLI_FLAG("quiet", 'q', &o->quiet, "no summary on stderr"),
        CLI_INT("threads", 0, &o->threads, "N", 1, INT_MAX,
                "threads of the per-triangle work and of the factorization (default 1)"),
        CLI_FLAG("deterministic", 0, &deterministic, "the same bytes for any --threads N (slower)"),
        CLI_STRING("report", 0, &o->report, "FILE.json",
                   "energy (area-matched), final_energy, max_handle_error, stop_reason, "
                   "iterations (docs/reports.md)"),
        CLI_STRING("svg", 0, &o->svg, "FILE", "picture of the deformed mesh"),
        CLI_PNG_OPTIONS(&o->png, "the same as PNG"),
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "deform",
                                     .usage = "usage: scaf deform IN.obj --targets T.json -o "
                                              "OUT.obj [options]\n\n",
                                     .about = about,
                                     .after = after,
                                     .options = options,
                                     .positionals = &o->in,
                                     .max_positionals = 1,
                                     .positional_name = "input"};
    int parsed = cli_options_parse(&cmd, argc, argv);
    if (parsed != CLI_OPTIONS_OK) {
        int rc = cli_options_done(&cmd, parsed);
        return rc == EXIT_OK ? -1 : rc; /* -1: help printed, exit 0 */
    }
    o->weight_given = !isnan(o->weight);
    if (deterministic) scaf_set_deterministic(1);
    if (!o->in || !o->out || !o->targets) {
        fprintf(stderr, "scaf deform: %s (see --help)\n",
                !o->in        ? "missing input mesh"
                    : !o->out ? "missing -o OUT.obj"
                              : "missing --targets FILE");
        return EXIT_USAGE;
    }
    if (cli_png_finish("deform", &o->png) < 0) return EXIT_USAGE;
    return EXIT_OK;
}

/* One iteration's record for the report. */
typedef struct step_record {
    int iteration;
    double energy, max_handle_error, step;
} step_record;

typedef struct progress_state {
    deform_options *opt;
    opt_handle_term *h; /* for the handle error only */
    int nv, nf;
    const int *F;
    int verify, not_bijective;
    step_record *rec;
    int n;
    cli_progress bar;
} progress_state;

static int on_iteration(const scaf_iteration_info_t *info, void *user)
{
    progress_state *s = user;
    double handle_error = opt_handle_term_max_error(s->h, s->opt->current);
    if (s->n < s->opt->iterations) {
        step_record r = {info->iteration, info->energy, handle_error, info->step};
        s->rec[s->n++] = r;
    }
    char extra[64];
    snprintf(extra, sizeof extra, "handle error %.3g", handle_error);
    cli_progress_step(&s->bar, info->iteration, info->energy, info->criterion, extra);
    cli_signal_test_point(info->iteration);
    if (cli_signal_caught()) return 1;
    if (s->verify) {
        bij_report rep;
        if (bij_check(s->nv, s->opt->current, s->nf, s->F, NULL, NULL, &rep, NULL) != SCAF_OK ||
            !rep.bijective) {
            s->not_bijective = info->iteration;
            return 1;
        }
    }
    return 0;
}

static scaf_status write_report(const char *path, const deform_args *a, int nh,
                                const deform_result *r, double energy, const progress_state *s,
                                scaf_error *err)
{
    FILE *f = fopen(path, "wb");
    if (!f) return err_set(err, SCAF_ERR_IO, "cannot write '%s'", path);
    json_write_report_head(f, "deform");
    fputs(",\n  \"input\": ", f);
    json_write_string(f, a->in);
    fputs(",\n  \"targets\": ", f);
    json_write_string(f, a->targets);
    fprintf(f, ",\n  \"handles\": %d,\n  \"remesh\": %s,\n  \"final_energy\": ", nh,
            a->no_remesh ? "false" : "true");
    json_write_number(f, r->energy);
    fputs(",\n  \"energy\": ", f);
    json_write_number(f, energy);
    fputs(",\n  \"max_handle_error\": ", f);
    json_write_number(f, r->max_handle_error);
    fprintf(f, ",\n  \"hard_targets\": %d,\n  \"hard_targets_met\": %d", r->hard, r->hard_reached);
    fprintf(f, ",\n  \"iteration_count\": %d,\n  \"stop_reason\": ", r->iterations);
    json_write_string(f, scaf_stop_reason_name(r->stop));
    fputs(",\n  \"iterations\": [", f);
    for (int i = 0; i < s->n; i++) {
        fprintf(f, "%s\n    {\"iteration\": %d, \"energy\": ", i ? "," : "", s->rec[i].iteration);
        json_write_number(f, s->rec[i].energy);
        fputs(", \"max_handle_error\": ", f);
        json_write_number(f, s->rec[i].max_handle_error);
        fputs(", \"step\": ", f);
        json_write_number(f, s->rec[i].step);
        fputc('}', f);
    }
    fputs("\n  ]\n}\n", f);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) return err_set(err, SCAF_ERR_IO, "cannot write '%s'", path);
    return SCAF_OK;
}

/* The planar rest positions (nv by 2) and faces of m: its vt when it has
 * them, else its v (which must have z = 0). Exit status. */
static int planar_mesh(const mesh *m, const char *in, int *nv, double **P, const int **F)
{
    if (mesh_has_uv(m)) {
        *nv = m->nuv;
        *F = m->FT;
        *P = malloc(sizeof(double) * 2 * (size_t)(m->nuv > 0 ? m->nuv : 1));
        if (!*P) return EXIT_NOMEM;
        memcpy(*P, m->UV, sizeof(double) * 2 * (size_t)m->nuv);
        return EXIT_OK;
    }
    for (int v = 0; v < m->nv; v++)
        if (m->V[3 * v + 2] != 0.0) {
            fprintf(stderr,
                    "scaf deform: %s: vertex %d has z = %g: give a planar mesh (z = 0) or one with "
                    "vt\n",
                    in, v + 1, m->V[3 * v + 2]);
            return EXIT_MESH;
        }
    *nv = m->nv;
    *F = m->F;
    *P = malloc(sizeof(double) * 2 * (size_t)(m->nv > 0 ? m->nv : 1));
    if (!*P) return EXIT_NOMEM;
    for (int v = 0; v < m->nv; v++) (*P)[2 * v] = m->V[3 * v], (*P)[2 * v + 1] = m->V[3 * v + 1];
    return EXIT_OK;
}

/* --png: every face in the colour of an undistorted one */
static unsigned rest_colour(int f, const void *ctx)
{
    (void)f, (void)ctx;
    return uv_svg_colour(4.0);
}

static int deform_main(int argc, char **argv)
{
    deform_args a;
    int rc = parse_args(argc, argv, &a);
    if (rc < 0) return EXIT_OK;
    if (rc != EXIT_OK) return rc;
    if (a.threads > 0) scaf_set_threads(a.threads); /* otherwise main's default */

    /* every output checked before any work; written all together at the end */
    cli_uv_job job;
    cli_uv_job_paths paths = {a.out, a.svg, a.png.path, a.report, "--targets", a.targets, NULL};
    mesh m;
    if ((rc = cli_uv_job_start(&job, "deform", a.in, &paths, a.quiet, &m)) != EXIT_OK) return rc;
    scaf_error err;
    err_clear(&err);
    deform_targets t = {0};
    double *P = NULL, *X = NULL, *V3 = NULL;
    step_record *rec = NULL;
    opt_handle_term h;
    opt_handle_term_init(&h, 2, 0);
    scaf_status st = deform_targets_read(a.targets, &t, &err);
    if (st == SCAF_ERR_CANCELLED) { /* the reader stopped at SIGINT / SIGTERM */
        fprintf(stderr, "scaf deform: %s; nothing written\n", err.message);
        rc = EXIT_CANCELLED;
        goto done;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf deform: %s\n", err.message);
        rc = exit_code_for(st);
        goto done;
    }
    int nv;
    const int *F;
    if ((rc = planar_mesh(&m, a.in, &nv, &P, &F)) != EXIT_OK) goto done;
    if ((st = deform_targets_check(&t, nv, P, a.targets, &err)) != SCAF_OK) {
        fprintf(stderr, "scaf deform: %s\n", err.message);
        rc = exit_code_for(st);
        goto done;
    }
    X = malloc(sizeof(double) * 2 * (size_t)(nv > 0 ? nv : 1));
    rec = malloc(sizeof *rec * (size_t)(a.iterations > 0 ? a.iterations : 1));
    if (!X || !rec) {
        fprintf(stderr, "scaf deform: out of memory\n");
        rc = EXIT_NOMEM;
        goto done;
    }
    h.nverts = nv;
    if ((st = opt_handle_term_set(&h, t.n, t.vertex, t.target, 1.0, &err)) != SCAF_OK) {
        fprintf(stderr, "scaf deform: %s: %s\n", a.targets, err.message);
        rc = exit_code_for(st);
        goto done;
    }

    deform_options o = deform_options_default();
    o.iterations = a.iterations;
    o.no_remesh = a.no_remesh;
    o.frame_iterations = a.frame_iterations;
    if (a.hard)
        for (int i = 0; i < t.n; i++) t.hard[i] = 1;
    o.hard = t.hard;
    o.npins = t.npins;
    o.pins = t.pins;
    if (t.has_weight) o.weight_ratio = t.weight;
    if (a.weight_given) o.weight_ratio = a.weight;
    progress_state ps = {&o, &h, nv, m.nf, F, a.verify, 0, rec, 0, {0}};
    o.progress = on_iteration;
    o.user = &ps;
    deform_result r;
    cli_progress_init(&ps.bar, "deform", a.quiet);
    cli_progress_phase(&ps.bar, "deform", o.iterations, 0, 0.0); /* a cap */
    st = deform_run(nv, P, m.nf, F, t.n, t.vertex, t.target, t.nframes, t.frames, &o, X, &r, &err);
    cli_progress_done(&ps.bar, NULL);
    if (cli_signal_report("deform")) {
        rc = EXIT_CANCELLED;
        goto done;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf deform: %s: %s%s\n", a.in, err.message,
                r.infeasible ? "; nothing written" : "");
        rc = r.infeasible ? EXIT_INFEASIBLE : exit_code_for(st);
        goto done;
    }
    if (r.infeasible) {
        fprintf(stderr,
                "scaf deform: %s: infeasible: %d of %d hard targets not met after %d iterations "
                "(%s; the largest miss %.3g): no flip-free placement on them was found, the "
                "pins and hard targets may admit no bijective map; nothing written\n",
                a.in, r.hard - r.hard_reached, r.hard, r.iterations,
                r.stop == SCAF_STOP_ITERATIONS ? "the --iterations cap"
                                               : "the run stalled or stopped",
                r.max_handle_error);
        rc = EXIT_INFEASIBLE;
        goto done;
    }
    if (ps.not_bijective) {
        fprintf(stderr, "scaf deform: %s: BUG: not bijective after iteration %d (please report)\n",
                a.in, ps.not_bijective);
        rc = EXIT_INTERNAL;
        goto done;
    }
    if (!a.quiet) {
        fprintf(stderr, "scaf deform: %d iterations, E %.6f, max handle error %.3g%s\n",
                r.iterations, r.energy, r.max_handle_error,
                a.verify ? " (bijective after every iteration: verified)" : "");
        if (r.hard > 0 || t.npins > 0)
            fprintf(stderr, "scaf deform: %d of %d hard targets met exactly, %d pins held\n",
                    r.hard_reached, r.hard, t.npins);
        fprintf(stderr, "scaf deform: stop reason: %s (%s)\n", scaf_stop_reason_name(r.stop),
                stop_reason_explained(r.stop));
    }

    V3 = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    if (!V3) {
        rc = EXIT_NOMEM;
        goto done;
    }
    /* the area-matched E of rest -> deformed (docs/energy.md), then V3
     * becomes the deformed positions */
    for (int v = 0; v < nv; v++)
        V3[3 * v] = P[2 * v], V3[3 * v + 1] = P[2 * v + 1], V3[3 * v + 2] = 0.0;
    double e_matched = NAN;
    scaf_area_matched_energy(V3, nv, F, m.nf, X, nv, F, &e_matched);
    for (int v = 0; v < nv; v++)
        V3[3 * v] = X[2 * v], V3[3 * v + 1] = X[2 * v + 1], V3[3 * v + 2] = 0.0;
    mesh out = {nv, V3, m.nf, (int *)F, nv, X, (int *)F};
    const char *path = cli_outputs_begin(&job.outs, job.k.mesh, &err);
    if ((rc = cli_outputs_end(&job.outs, job.k.mesh,
                              path ? mesh_write_obj(path, &out, &err) : SCAF_ERR_IO, &err)) !=
        EXIT_OK)
        goto done;
    if (a.svg) {
        char title[256];
        snprintf(title, sizeof title, "%s: max handle error %.3g after %d iterations", a.in,
                 r.max_handle_error, r.iterations);
        path = cli_outputs_begin(&job.outs, job.k.svg, &err);
        st = path ? uv_svg_write(path, nv, X, m.nf, F, NULL, NULL, title, &err) : SCAF_ERR_IO;
        if ((rc = cli_outputs_end(&job.outs, job.k.svg, st, &err)) != EXIT_OK) goto done;
    }
    if ((rc = cli_uv_job_png(&job, nv, X, m.nf, F, rest_colour, NULL, nv, V3, F, &a.png.opt)) !=
        EXIT_OK)
        goto done;
    if (a.report) {
        path = cli_outputs_begin(&job.outs, job.k.report, &err);
        st = path ? write_report(path, &a, t.n, &r, e_matched, &ps, &err) : SCAF_ERR_IO;
        if ((rc = cli_outputs_end(&job.outs, job.k.report, st, &err)) != EXIT_OK) goto done;
    }
    rc = cli_outputs_commit(&job.outs);
done:
    cli_outputs_abort(&job.outs);
    opt_handle_term_free(&h);
    deform_targets_free(&t);
    mesh_free(&m);
    free(P);
    free(X);
    free(V3);
    free(rec);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_deform(int argc, char **argv) { return cli_signal_run(deform_main, argc, argv); }
