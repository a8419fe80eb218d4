/* tools/cmd_untangle: `scaf untangle IN -o OUT.obj`, remove the
 * self-intersections of a closed genus-0 surface (app/untangle: cMCF out
 * until free, the 3D SCAF loop back toward the input).
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

#include "app/untangle.h"
#include "base/atomic_file.h"
#include "base/json_write.h"
#include "base/timer.h"
#include "cli_args.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "cli_surface_png.h"
#include "cli_unit_scale.h"
#include "exit_codes.h"
#include "mesh/mesh_io.h"

static void usage(FILE *out)
{
    untangle_options d = untangle_options_default();
    fprintf(out,
            "usage: scaf untangle IN -o OUT.obj [--iterations N] [--tolerance T] [--anchor W]\n"
            "                     [--flow-steps N] [--delta D] [--verify] [--report R.json]\n"
            "                     [--png P.png [--png-size N]] [--quiet]\n"
            "\n"
            "Remove the self-intersections of the closed genus-0 surface IN (Figure 9 of\n"
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
            "\n"
            "  -o, --output FILE  the OBJ to write (nothing is left on failure)\n"
            "  -n, --iterations N at most N iterations of the flow back (default %d)\n"
            "  --tolerance T      the flow back stops when %d iterations lowered the\n"
            "                     lowest energy so far by at most T times it, T in [0, 1)\n"
            "                     (default %g)\n"
            "  --anchor W         weight of the pull of every vertex toward its input\n"
            "                     position, >= 0 (default %g; 0: ARAP alone, which lets\n"
            "                     the whole surface drift)\n"
            "  --flow-steps N     at most N flow steps; fail (exit 6) if the surface is\n"
            "                     still not free (default %d)\n"
            "  --delta D          flow time step on the unit-area surface (default %g)\n"
            "  --verify           prove the surface free of self-intersections after every\n"
            "                     iteration too (exact; exit 70 if it ever is not)\n",
            d.iterations, UNTANGLE_WINDOW, d.tolerance, d.anchor_ratio, d.flow_steps, d.delta);
    fputs("  --report FILE      a JSON report: the flow steps (seconds, intersecting\n"
          "                     pairs, distance) and per iteration the surface energy,\n"
          "                     RMS and maximum distance of the vertices to their input\n"
          "                     positions (relative to the bounding-box diagonal),\n"
          "                     scaffold tets and quality, seconds\n" CLI_SURFACE_PNG_HELP(
              "the input, flowed and final surface side by side") "  -q, --quiet        no "
                                                                  "progress lines "
                                                                  "on stderr\n" CLI_OUTPUTS_HELP
                                                                  "\n",
          out);
    exit_codes_print(out);
}

typedef struct progress_state {
    int quiet;
    int events; /* flow steps and iterations so far: the signal test points */
} progress_state;

static int on_step(const untangle_event *e, void *user)
{
    progress_state *p = user;
    if (!p->quiet) {
        if (e->phase == UNTANGLE_FLOW)
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
    fprintf(o, "{\"%s\": %d, \"seconds\": ", e->phase == UNTANGLE_FLOW ? "step" : "iteration",
            e->step);
    json_write_number(o, e->seconds);
    if (e->phase == UNTANGLE_BACK) {
        fputs(", \"energy\": ", o);
        json_write_number(o, e->energy);
        fputs(", \"arap\": ", o);
        json_write_number(o, e->arap);
    }
    fputs(", \"rms\": ", o);
    json_write_number(o, e->rms);
    fputs(", \"max\": ", o);
    json_write_number(o, e->max);
    if (e->phase == UNTANGLE_BACK) {
        fprintf(o, ", \"tets\": %d, \"quality_min\": ", e->tets);
        json_write_number(o, e->quality);
    }
    if (e->pairs >= 0) fprintf(o, ", \"pairs\": %lld", e->pairs);
    fputc('}', o);
}

static scaf_status write_report(const char *path, const char *in, const untangle_options *opt,
                                const untangle_result *r, int nv, int nf, double seconds,
                                scaf_error *err)
{
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = a.f;
    fputs("{\n  \"input\": ", o);
    json_write_string(o, in);
    fprintf(o, ",\n  \"vertices\": %d,\n  \"faces\": %d,\n  \"diagonal\": ", nv, nf);
    json_write_number(o, r->diagonal);
    fprintf(o,
            ",\n  \"input_pairs\": %lld,\n  \"already_free\": %s,\n  \"delta\": ", r->input_pairs,
            r->stop == UNTANGLE_ALREADY_FREE ? "true" : "false");
    json_write_number(o, opt->delta);
    fprintf(o, ",\n  \"flow_steps\": %d,\n  \"flowed_rms\": ", r->flow_steps);
    json_write_number(o, r->flowed_rms);
    fputs(",\n  \"flowed_max\": ", o);
    json_write_number(o, r->flowed_max);
    fputs(",\n  \"anchor\": ", o);
    json_write_number(o, opt->anchor_ratio);
    fprintf(o,
            ",\n  \"iterations\": %d,\n  \"best_iteration\": %d,\n  \"stop_reason\": \"%s\",\n  "
            "\"rms\": ",
            r->iterations, r->best_iteration, untangle_stop_name(r->stop));
    json_write_number(o, r->rms);
    fputs(",\n  \"max\": ", o);
    json_write_number(o, r->max);
    fprintf(o, ",\n  \"verified_every_iteration\": %s,\n  \"seconds\": ",
            opt->verify ? "true" : "false");
    json_write_number(o, seconds);
    for (int phase = 0; phase < 2; phase++) {
        fputs(phase ? ",\n  \"per_iteration\": [" : ",\n  \"per_flow_step\": [", o);
        int first = 1;
        for (int i = 0; i < r->nlog; i++) {
            if ((int)r->log[i].phase != phase) continue;
            fputs(first ? "\n    " : ",\n    ", o);
            write_event(o, &r->log[i]);
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
    untangle_options opt = untangle_options_default();
    int quiet = 0;
    cli_surface_png png;
    cli_surface_png_init(&png);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int taken = cli_surface_png_option("untangle", argc, argv, &i, &png);
        if (taken < 0) return EXIT_USAGE;
        if (taken) continue;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            CLI_NEED_VALUE("untangle");
            out = v;
        } else if (!strcmp(a, "-n") || !strcmp(a, "--iterations")) {
            CLI_NEED_VALUE("untangle");
            if (!cli_parse_int(v, &opt.iterations)) CLI_BAD_VALUE("untangle");
        } else if (!strcmp(a, "--flow-steps")) {
            CLI_NEED_VALUE("untangle");
            if (!cli_parse_int(v, &opt.flow_steps)) CLI_BAD_VALUE("untangle");
        } else if (!strcmp(a, "--tolerance")) {
            CLI_NEED_VALUE("untangle");
            if (!cli_parse_double(v, &opt.tolerance)) CLI_BAD_VALUE("untangle");
        } else if (!strcmp(a, "--anchor")) {
            CLI_NEED_VALUE("untangle");
            if (!cli_parse_double(v, &opt.anchor_ratio)) CLI_BAD_VALUE("untangle");
        } else if (!strcmp(a, "--delta")) {
            CLI_NEED_VALUE("untangle");
            if (!cli_parse_double(v, &opt.delta)) CLI_BAD_VALUE("untangle");
        } else if (!strcmp(a, "--report")) {
            CLI_NEED_VALUE("untangle");
            report = v;
        } else if (!strcmp(a, "--verify")) {
            opt.verify = 1;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            quiet = 1;
        } else if (cli_take_input("untangle", a, &in) != EXIT_OK) {
            return EXIT_USAGE;
        }
    }
    if (!in || !out) {
        fprintf(stderr, "scaf untangle: %s (see --help)\n",
                !in ? "missing the input surface" : "missing -o OUT.obj");
        return EXIT_USAGE;
    }
    scaf_error err;
    err_clear(&err);
    if (untangle_options_check(&opt, &err) != SCAF_OK) {
        fprintf(stderr, "scaf untangle: %s\n", err.message);
        return EXIT_USAGE;
    }
    if (cli_surface_png_finish("untangle", &png) < 0) return EXIT_USAGE;
    cli_outputs outs;
    cli_outputs_init(&outs, "untangle", in);
    int k = cli_outputs_add(&outs, "-o", out, CLI_OUTPUT_MESH);
    int kr = cli_outputs_add(&outs, "--report", report, CLI_OUTPUT_FILE);
    int kp = cli_outputs_add(&outs, "--png", png.path, CLI_OUTPUT_FILE);
    int rc = cli_outputs_check(&outs);
    if (rc != EXIT_OK) return rc;
    mesh m;
    mesh_read_info info;
    if ((rc = cli_read_mesh("untangle", in, quiet, &m, &info)) != EXIT_OK) return rc;
    /* at unit scale (tools/cli_unit_scale): areas overflow at 1e300 and
     * vanish at 1e-300; the results are multiplied back before writing */
    int e = 0;
    if ((rc = cli_unit_scale("untangle", in, &m, &e)) != EXIT_OK) {
        mesh_free(&m);
        return rc;
    }
    progress_state ps = {quiet, 0};
    untangle_result r;
    double t0 = timer_now();
    scaf_status st = untangle_run(m.nv, m.V, m.nf, m.F, &opt, on_step, &ps, &r, &err);
    double seconds = timer_now() - t0;
    if (st != SCAF_OK) {
        if (!cli_signal_report("untangle"))
            fprintf(stderr, "scaf untangle: %s: %s\n", in, err.message);
        mesh_free(&m);
        return exit_code_for(st);
    }
    if (!quiet) {
        if (r.stop == UNTANGLE_ALREADY_FREE)
            fprintf(stderr,
                    "scaf untangle: %s is already free of self-intersections: written "
                    "unchanged\n",
                    in);
        else
            fprintf(stderr,
                    "scaf untangle: %lld intersecting face pairs, free after %d flow steps "
                    "(distance RMS %.4g), %d iterations back (%s): distance RMS %.4g max %.4g, "
                    "%.2f s\n",
                    r.input_pairs, r.flow_steps, r.flowed_rms, r.iterations,
                    untangle_stop_name(r.stop), r.rms, r.max, seconds);
    }
    if (cli_signal_report("untangle")) rc = EXIT_CANCELLED;
    size_t n3 = 3 * (size_t)m.nv;
    if (rc == EXIT_OK) rc = cli_unit_unscale("untangle", in, m.V, n3, e);
    if (rc == EXIT_OK) rc = cli_unit_unscale("untangle", in, r.X, n3, e);
    if (rc == EXIT_OK && r.flowed) rc = cli_unit_unscale("untangle", in, r.flowed, n3, e);
    r.diagonal = ldexp(r.diagonal, e); /* distances are relative to it: unchanged */
    if (rc == EXIT_OK) {
        /* the input's mesh (and its UVs, if any) at the final positions */
        double *V = m.V;
        m.V = r.X;
        const char *path = cli_outputs_begin(&outs, k, &err);
        rc = cli_outputs_end(&outs, k, path ? mesh_write_obj(path, &m, &err) : SCAF_ERR_IO, &err);
        m.V = V;
        if (rc == EXIT_OK && kr >= 0) {
            path = cli_outputs_begin(&outs, kr, &err);
            rc = cli_outputs_end(&outs, kr,
                                 path ? write_report(path, in, &opt, &r, m.nv, m.nf, seconds, &err)
                                      : SCAF_ERR_IO,
                                 &err);
        }
        surface_view panels[3] = {{m.nv, m.V, m.nf, m.F, NULL, 0, NULL},
                                  {m.nv, r.flowed, m.nf, m.F, NULL, 0, NULL},
                                  {m.nv, r.X, m.nf, m.F, NULL, 0, NULL}};
        int n = r.stop == UNTANGLE_ALREADY_FREE ? 1 : 3;
        if (rc == EXIT_OK) rc = cli_surface_png_write(&outs, kp, n, panels, &png);
        if (rc == EXIT_OK) rc = cli_outputs_commit(&outs);
    }
    cli_outputs_abort(&outs);
    untangle_result_free(&r);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_untangle(int argc, char **argv) { return cli_signal_run(untangle_main, argc, argv); }
