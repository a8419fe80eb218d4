/* tools/cmd_flow: `scaf flow IN -o OUT --steps N`, conformalized mean
 * curvature flow of a closed surface (scaf_flow, scaf/volume.h).
 *
 * The surface is normalized (area-weighted centroid at the origin, unit
 * area: --delta then means the same for every input) and flowed N steps;
 * with --until-free the run stops at the first step whose surface the
 * exact checker proves free of self-intersections,
 * and fails (exit 6, nothing written) when none of the N steps is. The
 * output is an OBJ with the input's vertices and faces at the flowed,
 * normalized positions. Exit status: 0 written, 2 usage, 3 input
 * unreadable, 4 not a closed manifold surface without zero-area faces,
 * 5 output not written, 6 the flow failed or did not free the surface,
 * 7 out of memory, 8 interrupted. --report writes a JSON of the steps,
 * --png a picture of the input and the flowed surface side by side.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/json_write.h"
#include "base/timer.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_progress.h"
#include "cli_signal.h"
#include "cli_surface_png.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"
#include "scaf/volume.h"

#define FLOW_MAX_STEPS 100000

static void about(FILE *out)
{
    fputs("Conformalized mean curvature flow (Kazhdan, Solomon, Ben-Chen 2012) of the\n"
          "closed surface IN: it becomes rounder at every step and, after a few, free of\n"
          "self-intersections. The surface is first moved and scaled to unit area\n"
          "(area-weighted centroid at the origin); every step solves\n"
          "(M - D L) U' = M U (L: cotangent Laplacian of IN, M: barycentric mass of the\n"
          "current shape) and normalizes again. Writes the input's vertices and faces at\n"
          "the flowed positions, in that normalized frame.\n"
          "\n",
          out);
}

static void after(FILE *out)
{
    fputs(CLI_OUTPUTS_HELP "\n", out);
    exit_codes_print(out);
}

/* What the run did, for --report. */
typedef struct flow_log {
    int steps;               /* steps done */
    double *seconds;         /* per step (steps entries; room for the maximum) */
    long long *defects;      /* per step with --until-free: intersecting pairs + zero-area faces */
    long long input_defects; /* -1 without --until-free */
} flow_log;

static scaf_status write_report(const char *path, const char *in, double delta, int until_free,
                                const flow_log *g, scaf_error *err)
{
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = a.f;
    json_write_report_head(o, "flow");
    fputs(",\n  \"input\": ", o);
    json_write_string(o, in);
    fputs(",\n  \"delta\": ", o);
    json_write_number(o, delta);
    fprintf(o, ",\n  \"until_free\": %s,\n  \"flow_steps\": %d", until_free ? "true" : "false",
            g->steps);
    if (until_free)
        fprintf(o, ",\n  \"input_defects\": %lld,\n  \"intersection_free\": %s", g->input_defects,
                (g->steps ? g->defects[g->steps - 1] : g->input_defects) == 0 ? "true" : "false");
    fputs(",\n  \"flow\": [", o);
    for (int s = 0; s < g->steps; s++) {
        fprintf(o, "%s\n    {\"step\": %d, \"seconds\": ", s ? "," : "", s + 1);
        json_write_number(o, g->seconds[s]);
        if (until_free) fprintf(o, ", \"defects\": %lld", g->defects[s]);
        fputc('}', o);
    }
    fputs("\n  ]\n}\n", o);
    return atomic_commit(&a, err);
}

/* The progress of scaf_flow: the step lines, the report's log, the
 * signal's safe point. */
typedef struct flow_watch {
    int until_free, quiet;
    flow_log *g;
    char what[128]; /* the last check, for the lines */
    double *start;  /* NULL, or room for the normalized input */
    int nv;
    cli_progress bar;
} flow_watch;

static void describe(const scaf_volume_step_info_t *e, char *what, size_t size)
{
    if (e->degenerate_faces > 0)
        snprintf(what, size, "%lld intersecting face pairs, %d zero-area faces", e->pairs,
                 e->degenerate_faces);
    else snprintf(what, size, "%lld intersecting face pairs", e->pairs);
}

static int on_flow_step(const scaf_volume_step_info_t *e, void *user)
{
    flow_watch *w = user;
    if (w->until_free) describe(e, w->what, sizeof w->what);
    if (e->step == 0) { /* the start: the normalized input, checked with until_free */
        if (w->start) memcpy(w->start, e->X, sizeof(double) * 3 * (size_t)w->nv);
        if (!w->until_free) return 0;
        cli_progress_clear(&w->bar); /* an ordinary line follows */
        w->g->input_defects = e->defects;
        if (e->defects == 0 && !w->quiet)
            fprintf(stderr, "scaf flow: the input is already free of self-intersections\n");
        else if (e->defects > 0 && !w->quiet) fprintf(stderr, "scaf flow: input: %s\n", w->what);
        return 0;
    }
    w->g->seconds[w->g->steps] = e->seconds;
    w->g->defects[w->g->steps++] = e->defects;
    cli_progress_step(&w->bar, e->step, NAN, NAN, w->until_free ? w->what : NULL);
    if (!w->quiet && !cli_progress_live(&w->bar)) {
        if (w->until_free)
            fprintf(stderr, "scaf flow: step %d: %.3f s, check %.3f s, %s\n", e->step, e->seconds,
                    e->check_seconds, w->what);
        else fprintf(stderr, "scaf flow: step %d: %.3f s\n", e->step, e->seconds);
    }
    cli_signal_test_point(e->step);
    return cli_signal_caught() != 0;
}

/* Flow m->V in place (scaf_flow: normalized, at unit scale inside); the
 * normalized input is copied to start (NULL: not kept). 0, or the exit
 * status after printing why. */
static int run_flow(const char *in, mesh *m, int steps, double delta, int until_free, int quiet,
                    flow_log *g, double *start)
{
    scaf_flow_options_t o = scaf_flow_options_default();
    o.steps = steps;
    o.delta = delta;
    o.until_free = until_free;
    flow_watch w = {until_free, quiet, g, "", start, m->nv, {0}};
    scaf_volume_t *h = scaf_volume_new();
    if (!h) {
        fprintf(stderr, "scaf flow: out of memory\n");
        return EXIT_NOMEM;
    }
    int rc = EXIT_OK;
    cli_progress_init(&w.bar, "flow", quiet);
    /* with until_free, steps is a cap the check ends first */
    cli_progress_phase(&w.bar, "flow", steps, !until_free, 0.0);
    scaf_status st = scaf_flow(h, m->V, m->nv, m->F, m->nf, &o, on_flow_step, &w);
    cli_progress_done(&w.bar, NULL);
    if (st == SCAF_OK) {
        scaf_volume_summary_t s = {.struct_size = sizeof s};
        scaf_volume_get_summary(h, &s);
        scaf_volume_get_positions(h, m->V);
        if (until_free && s.steps > 0 && !quiet)
            fprintf(stderr, "scaf flow: free of self-intersections after %d step%s\n", s.steps,
                    s.steps > 1 ? "s" : "");
    } else if (!(st == SCAF_ERR_CANCELLED && cli_signal_caught())) {
        if (st == SCAF_ERR_NUMERIC && until_free && g->steps == steps)
            fprintf(stderr, "scaf flow: %s; nothing written\n", scaf_volume_error(h));
        else fprintf(stderr, "scaf flow: %s: %s\n", in, scaf_volume_error(h));
        rc = exit_code_for(st);
    }
    scaf_volume_destroy(h);
    return rc;
}

static int flow_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *report = NULL;
    double delta = 1e-3;
    int steps = 0, until_free = 0, quiet = 0;
    cli_surface_png png;
    cli_surface_png_init(&png);
    const cli_option options[] = {
        CLI_STRING("output", 'o', &out, "FILE", "the OBJ to write (nothing is left on failure)"),
        CLI_INT("steps", 'n', &steps, "N", 1, FLOW_MAX_STEPS,
                "steps to run, 1..100000 (with --until-free: at most N)"),
        CLI_DOUBLE("delta", 0, &delta, "D", 0, 1e6, "time step, > 0 (default 1e-3)", .open_min = 1),
        CLI_FLAG("until-free", 0, &until_free,
                 "stop at the first step whose surface is free of self-intersections (exact "
                 "check after every step); fail (exit 6) if none of the N steps is"),
        CLI_STRING("report", 0, &report, "FILE",
                   "a JSON report: delta, steps done, whether the result is free, and per step "
                   "its seconds (with --until-free its defects: intersecting face pairs + "
                   "zero-area faces)"),
        CLI_SURFACE_PNG_OPTIONS(&png, "the input and the flowed surface side by side"),
        CLI_FLAG("quiet", 'q', &quiet,
                 "no per-step lines on stderr (step, seconds, and with --until-free the "
                 "intersecting face pairs)"),
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "flow",
                                     .usage = "usage: scaf flow IN -o OUT.obj --steps N [--delta "
                                              "D] [--until-free] [--report "
                                              "R.json]\n"
                                              "                 [--png P.png [--png-size N]] "
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
    if (!in || !out || !steps) {
        fprintf(stderr, "scaf flow: %s (see --help)\n",
                !in        ? "missing the input surface"
                    : !out ? "missing -o OUT.obj"
                           : "missing --steps N");
        return EXIT_USAGE;
    }
    if (cli_surface_png_finish("flow", &png) < 0) return EXIT_USAGE;
    cli_outputs outs;
    cli_outputs_init(&outs, "flow", in);
    int k = cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
    int kr = cli_outputs_add(&outs, "--report", report, CLI_OUTPUT_FILE);
    int kp = cli_outputs_add(&outs, "--png", png.path, CLI_OUTPUT_FILE);
    int rc = cli_outputs_check(&outs);
    if (rc != EXIT_OK) return rc;
    mesh m;
    mesh_read_info info;
    if ((rc = cli_read_mesh("flow", in, quiet, &m, &info)) != EXIT_OK) return rc;
    flow_log g = {0, malloc(sizeof(double) * (size_t)steps),
                  malloc(sizeof(long long) * (size_t)steps), -1};
    double *start = kp >= 0 ? malloc(sizeof(double) * 3 * (size_t)(m.nv > 0 ? m.nv : 1)) : NULL;
    if (!g.seconds || !g.defects || (kp >= 0 && !start)) {
        fprintf(stderr, "scaf flow: out of memory\n");
        rc = EXIT_NOMEM;
    } else {
        rc = run_flow(in, &m, steps, delta, until_free, quiet, &g, start);
    }
    if (rc == EXIT_OK && cli_signal_report("flow")) rc = EXIT_CANCELLED;
    if (rc == EXIT_OK) {
        scaf_error err;
        err_clear(&err);
        const char *path = cli_outputs_begin(&outs, k, &err);
        rc = cli_outputs_end(&outs, k, path ? mesh_write_obj(path, &m, &err) : SCAF_ERR_IO, &err);
        if (rc == EXIT_OK && kr >= 0) {
            path = cli_outputs_begin(&outs, kr, &err);
            rc = cli_outputs_end(
                &outs, kr, path ? write_report(path, in, delta, until_free, &g, &err) : SCAF_ERR_IO,
                &err);
        }
        surface_view panels[2] = {{m.nv, start, m.nf, m.F, NULL, 0, NULL, "input"},
                                  {m.nv, m.V, m.nf, m.F, NULL, 0, NULL, "flowed"}};
        if (rc == EXIT_OK) rc = cli_surface_png_write(&outs, kp, 2, panels, &png);
        if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    }
    cli_outputs_abort(&outs);
    free(g.seconds);
    free(g.defects);
    free(start);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_flow(int argc, char **argv) { return cli_signal_run(flow_main, argc, argv); }
