/* tools/cmd_untangle: `scaf untangle IN -o OUT.obj`, remove the
 * self-intersections of a closed genus-0 surface (scaf_untangle of the
 * public scaf/volume.h: cMCF out until free, the 3D SCAF loop back toward
 * the input).
 *
 * Writes the input's vertices and faces at the final positions (an input
 * already free of self-intersections unchanged, with a message), and with
 * --report a JSON of the flow steps and the iterations, with --png the
 * input, the flowed and the final surface side by side. Exit status: 0
 * written, 2 usage, 3 input unreadable, 4 not a closed manifold genus-0
 * surface (the message says why), 5 output not written, 6 the flow did
 * not free the surface or a solve failed, 7 out of memory, 8 interrupted,
 * 70 an exact check failed (a bug). Nothing is written on failure.
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

static void about(FILE *out)
{
    fputs("Remove the self-intersections of the closed genus-0 surface IN (Figure 9 of\n"
          "the SCAF paper). First conformalized mean curvature flow rounds it, step by\n"
          "step, until the exact checker proves it free of self-intersections; then the\n"
          "3D SCAF loop pulls it back toward IN: tets fill a box around the surface,\n"
          "inside and outside, a surface ARAP term pulls toward IN's shape (rotations\n"
          "re-fitted every iteration), an anchor toward IN's positions, and no tet may\n"
          "ever invert (each iteration local flips and edge and face removals reshape\n"
          "the worst scaffold tets), so the surface can touch itself but never pass\n"
          "through. Writes IN's vertices and faces at the positions of lowest energy.\n"
          "An input already free is written unchanged. Genus > 0 is refused: the flow\n"
          "thins a handle into a ring instead of rounding it.\n"
          "\n",
          out);
}

static void after(FILE *out)
{
    fputs(CLI_OUTPUTS_HELP "\n", out);
    exit_codes_print(out);
}

/* One step of either phase, as the progress callback gave it. */
typedef struct untangle_event {
    scaf_volume_phase phase;
    int step;
    double seconds;
    long long pairs; /* intersecting pairs + zero-area faces (-1 unchecked) */
    double energy, arap, rms, max;
    int tets;
    double quality;
} untangle_event;

typedef struct progress_state {
    int quiet;
    int events; /* flow steps and iterations so far: the signal test points */
    int nlog, cap;
    untangle_event *log; /* every step, for --report */
    int nomem;
    cli_progress bar;
    int flow_cap, iteration_cap;
    int in_flow; /* the bar's phase: 1 flow, 0 iterations back, -1 none yet */
} progress_state;

static int on_step(const scaf_volume_step_info_t *i, void *user)
{
    progress_state *p = user;
    untangle_event ev = {i->phase, i->step, i->seconds, i->defects, i->energy,
                         i->arap,  i->rms,  i->max,     i->tets,    i->quality_min};
    const untangle_event *e = &ev;
    if (p->nlog == p->cap) {
        int n = p->cap ? 2 * p->cap : 64;
        untangle_event *g = realloc(p->log, sizeof *g * (size_t)n);
        if (!g) {
            p->nomem = 1;
            return 1;
        }
        p->log = g;
        p->cap = n;
    }
    p->log[p->nlog++] = ev;
    int flow = e->phase == SCAF_VOLUME_FLOW_STEP;
    if (flow != p->in_flow) {
        p->in_flow = flow;
        if (flow) cli_progress_phase(&p->bar, "flow", p->flow_cap, 0, 0.0);
        else cli_progress_phase(&p->bar, "untangle", p->iteration_cap, 0, 0.0);
    }
    char extra[96];
    if (flow) snprintf(extra, sizeof extra, "%lld intersecting pairs", e->pairs);
    else snprintf(extra, sizeof extra, "distance RMS %.3g", e->rms);
    cli_progress_step(&p->bar, e->step, flow ? NAN : e->energy, NAN, extra);
    if (!p->quiet && !cli_progress_live(&p->bar)) {
        if (e->phase == SCAF_VOLUME_FLOW_STEP)
            fprintf(stderr,
                    "scaf untangle: flow step %d: %lld intersecting face pairs, distance RMS "
                    "%.4g max %.4g, %.3f s\n",
                    e->step, e->pairs, e->rms, e->max, e->seconds);
        else
            fprintf(stderr,
                    "scaf untangle: iteration %d: energy %.6g, distance RMS %.4g max %.4g, "
                    "%d tets (min quality %.3g), %.3f s%s\n",
                    e->step, e->energy, e->rms, e->max, e->tets, e->quality, e->seconds,
                    e->pairs == 0 ? ", free" : "");
    }
    cli_signal_test_point(++p->events);
    return cli_signal_caught() != 0;
}

static void write_event(FILE *o, const untangle_event *e)
{
    fprintf(o,
            "{\"%s\": %d, \"seconds\": ", e->phase == SCAF_VOLUME_FLOW_STEP ? "step" : "iteration",
            e->step);
    json_write_number(o, e->seconds);
    if (e->phase == SCAF_VOLUME_ITERATION) {
        fputs(", \"energy\": ", o);
        json_write_number(o, e->energy);
        fputs(", \"arap\": ", o);
        json_write_number(o, e->arap);
    }
    fputs(", \"rms\": ", o);
    json_write_number(o, e->rms);
    fputs(", \"max\": ", o);
    json_write_number(o, e->max);
    if (e->phase == SCAF_VOLUME_ITERATION) {
        fprintf(o, ", \"tets\": %d, \"quality_min\": ", e->tets);
        json_write_number(o, e->quality);
    }
    if (e->pairs >= 0) fprintf(o, ", \"pairs\": %lld", e->pairs);
    fputc('}', o);
}

static scaf_status write_report(const char *path, const char *in,
                                const scaf_untangle_options_t *opt, const scaf_volume_summary_t *r,
                                const progress_state *log, int nv, int nf, double seconds,
                                scaf_error *err)
{
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = a.f;
    json_write_report_head(o, "untangle");
    fputs(",\n  \"input\": ", o);
    json_write_string(o, in);
    fprintf(o, ",\n  \"mesh\": {\"vertices\": %d, \"faces\": %d},\n  \"diagonal\": ", nv, nf);
    json_write_number(o, r->diagonal_before);
    fprintf(o,
            ",\n  \"input_pairs\": %lld,\n  \"already_free\": %s,\n  \"delta\": ", r->input_defects,
            r->stop == SCAF_UNTANGLE_ALREADY_FREE ? "true" : "false");
    json_write_number(o, opt->delta);
    fprintf(o, ",\n  \"flow_steps\": %d,\n  \"flowed_rms\": ", r->steps);
    json_write_number(o, r->flowed_rms);
    fputs(",\n  \"flowed_max\": ", o);
    json_write_number(o, r->flowed_max);
    fputs(",\n  \"anchor\": ", o);
    json_write_number(o, opt->anchor);
    fprintf(o,
            ",\n  \"iteration_count\": %d,\n  \"best_iteration\": %d,\n  \"stop_reason\": "
            "\"%s\",\n  "
            "\"rms\": ",
            r->iterations, r->best_iteration, scaf_untangle_stop_name(r->stop));
    json_write_number(o, r->rms);
    fputs(",\n  \"max\": ", o);
    json_write_number(o, r->max);
    fprintf(o, ",\n  \"verified_every_iteration\": %s,\n  \"seconds\": ",
            opt->verify ? "true" : "false");
    json_write_number(o, seconds);
    for (int phase = 0; phase < 2; phase++) {
        fputs(phase ? ",\n  \"iterations\": [" : ",\n  \"flow\": [", o);
        int first = 1;
        for (int i = 0; i < log->nlog; i++) {
            if ((int)log->log[i].phase != phase) continue;
            fputs(first ? "\n    " : ",\n    ", o);
            write_event(o, &log->log[i]);
            first = 0;
        }
        fputs("\n  ]", o);
    }
    fputs("\n}\n", o);
    return atomic_commit(&a, err);
}

static int untangle_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *report = NULL;
    scaf_untangle_options_t opt = scaf_untangle_options_default();
    int quiet = 0;
    cli_surface_png png;
    cli_surface_png_init(&png);
    char help_n[96], help_tol[192], help_anchor[192], help_flow[128], help_delta[96];
    snprintf(help_n, sizeof help_n, "at most N iterations of the flow back (default %d)",
             opt.iterations);
    snprintf(help_tol, sizeof help_tol,
             "the flow back stops when %d iterations lowered the lowest energy so far by at "
             "most T times it, T in [0, 1) (default %g)",
             SCAF_UNTANGLE_WINDOW, opt.tolerance);
    snprintf(help_anchor, sizeof help_anchor,
             "weight of the pull of every vertex toward its input position, >= 0 (default %g; "
             "0: ARAP alone, which lets the whole surface drift)",
             opt.anchor);
    snprintf(help_flow, sizeof help_flow,
             "at most N flow steps; fail (exit 6) if the surface is still not free (default %d)",
             opt.flow_steps);
    snprintf(help_delta, sizeof help_delta, "flow time step on the unit-area surface (default %g)",
             opt.delta);
    /* ranges: scaf_untangle checks them (below), so each is written once */
    const cli_option options[] = {
        CLI_STRING("output", 'o', &out, "FILE", "the OBJ to write (nothing is left on failure)"),
        CLI_INT("iterations", 'n', &opt.iterations, "N", 0, 0, help_n),
        CLI_DOUBLE("tolerance", 0, &opt.tolerance, "T", 0, 0, help_tol),
        CLI_DOUBLE("anchor", 0, &opt.anchor, "W", 0, 0, help_anchor),
        CLI_INT("flow-steps", 0, &opt.flow_steps, "N", 0, 0, help_flow),
        CLI_DOUBLE("delta", 0, &opt.delta, "D", 0, 0, help_delta),
        CLI_FLAG("verify", 0, &opt.verify,
                 "prove the surface free of self-intersections after every iteration too "
                 "(exact; exit 70 if it ever is not)"),
        CLI_STRING("report", 0, &report, "FILE",
                   "a JSON report: the flow steps (seconds, intersecting pairs, distance) and "
                   "per iteration the surface energy, RMS and maximum distance of the vertices "
                   "to their input positions (relative to the bounding-box diagonal), scaffold "
                   "tets and quality, seconds"),
        CLI_SURFACE_PNG_OPTIONS(&png, "the input, flowed and final surface side by side"),
        CLI_FLAG("quiet", 'q', &quiet, "no progress lines on stderr"),
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "untangle",
                                     .usage = "usage: scaf untangle IN -o OUT.obj [--iterations N] "
                                              "[--tolerance T] [--anchor W]\n"
                                              "                     [--flow-steps N] [--delta D] "
                                              "[--verify] [--report R.json]\n"
                                              "                     [--png P.png [--png-size N]] "
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
    if (!in || !out) {
        fprintf(stderr, "scaf untangle: %s (see --help)\n",
                !in ? "missing the input surface" : "missing -o OUT.obj");
        return EXIT_USAGE;
    }
    /* the options first (exit 2 before reading anything): with no surface
     * scaf_untangle checks them alone */
    scaf_volume_t *h = scaf_volume_new();
    if (!h) {
        fprintf(stderr, "scaf untangle: out of memory\n");
        return EXIT_NOMEM;
    }
    if (scaf_untangle(h, NULL, 0, NULL, 0, &opt, NULL, NULL) == SCAF_ERR_USAGE) {
        fprintf(stderr, "scaf untangle: %s\n", scaf_volume_error(h));
        scaf_volume_destroy(h);
        return EXIT_USAGE;
    }
    int rc = cli_surface_png_finish("untangle", &png) < 0 ? EXIT_USAGE : EXIT_OK;
    cli_outputs outs;
    int k = -1, kr = -1, kp = -1;
    if (rc == EXIT_OK) {
        cli_outputs_init(&outs, "untangle", in);
        k = cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
        kr = cli_outputs_add(&outs, "--report", report, CLI_OUTPUT_FILE);
        kp = cli_outputs_add(&outs, "--png", png.path, CLI_OUTPUT_FILE);
        rc = cli_outputs_check(&outs);
    }
    mesh m;
    mesh_read_info info;
    if (rc == EXIT_OK) rc = cli_read_mesh("untangle", in, quiet, &m, &info);
    if (rc != EXIT_OK) {
        scaf_volume_destroy(h);
        return rc;
    }
    progress_state ps = {quiet, 0, 0, 0, NULL, 0, {0}, opt.flow_steps, opt.iterations, -1};
    cli_progress_init(&ps.bar, "untangle", quiet);
    double t0 = timer_now();
    scaf_status st = scaf_untangle(h, m.V, m.nv, m.F, m.nf, &opt, on_step, &ps);
    cli_progress_done(&ps.bar, NULL);
    double seconds = timer_now() - t0;
    size_t n3 = 3 * (size_t)m.nv;
    double *X = st == SCAF_OK ? malloc(sizeof(double) * n3) : NULL;
    double *flowed = st == SCAF_OK ? malloc(sizeof(double) * n3) : NULL;
    if (st == SCAF_OK && (!X || !flowed)) st = SCAF_ERR_NOMEM;
    if (ps.nomem) st = SCAF_ERR_NOMEM;
    if (st != SCAF_OK) {
        if (st == SCAF_ERR_NOMEM) fprintf(stderr, "scaf untangle: out of memory\n");
        else if (!cli_signal_report("untangle"))
            fprintf(stderr, "scaf untangle: %s: %s\n", in, scaf_volume_error(h));
        free(X);
        free(flowed);
        free(ps.log);
        scaf_volume_destroy(h);
        mesh_free(&m);
        return exit_code_for(st);
    }
    scaf_volume_get_positions(h, X);
    scaf_volume_get_flowed(h, flowed);
    scaf_volume_summary_t r = {.struct_size = sizeof r};
    scaf_volume_get_summary(h, &r);
    if (!quiet) {
        if (r.stop == SCAF_UNTANGLE_ALREADY_FREE)
            fprintf(stderr,
                    "scaf untangle: %s is already free of self-intersections: written "
                    "unchanged\n",
                    in);
        else
            fprintf(stderr,
                    "scaf untangle: %lld intersecting face pairs, free after %d flow steps "
                    "(distance RMS %.4g), %d iterations back (%s): distance RMS %.4g max %.4g, "
                    "%.2f s\n",
                    r.input_defects, r.steps, r.flowed_rms, r.iterations,
                    scaf_untangle_stop_name(r.stop), r.rms, r.max, seconds);
    }
    if (cli_signal_report("untangle")) rc = EXIT_CANCELLED;
    if (rc == EXIT_OK) {
        scaf_error err;
        err_clear(&err);
        /* the input's mesh (and its UVs, if any) at the final positions */
        double *V = m.V;
        m.V = X;
        const char *path = cli_outputs_begin(&outs, k, &err);
        rc = cli_outputs_end(&outs, k, path ? mesh_write_obj(path, &m, &err) : SCAF_ERR_IO, &err);
        m.V = V;
        if (rc == EXIT_OK && kr >= 0) {
            path = cli_outputs_begin(&outs, kr, &err);
            rc = cli_outputs_end(
                &outs, kr,
                path ? write_report(path, in, &opt, &r, &ps, m.nv, m.nf, seconds, &err)
                     : SCAF_ERR_IO,
                &err);
        }
        surface_view panels[3] = {{m.nv, m.V, m.nf, m.F, NULL, 0, NULL, "input"},
                                  {m.nv, flowed, m.nf, m.F, NULL, 0, NULL, "flowed"},
                                  {m.nv, X, m.nf, m.F, NULL, 0, NULL, "untangled"}};
        int n = r.stop == SCAF_UNTANGLE_ALREADY_FREE ? 1 : 3;
        if (rc == EXIT_OK) rc = cli_surface_png_write(&outs, kp, n, panels, &png);
        if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    }
    cli_outputs_abort(&outs);
    free(X);
    free(flowed);
    free(ps.log);
    scaf_volume_destroy(h);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_untangle(int argc, char **argv) { return cli_signal_run(untangle_main, argc, argv); }
