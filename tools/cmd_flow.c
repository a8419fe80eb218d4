/* tools/cmd_flow: `scaf flow IN -o OUT --steps N`, conformalized mean
 * curvature flow of a closed surface (opt/cmcf).
 *
 * The surface is normalized (area-weighted centroid at the origin, unit
 * area: --delta then means the same for every input) and flowed N steps;
 * with --until-free the run stops at the first step whose surface the
 * exact checker (geom/self_intersect) proves free of self-intersections,
 * and fails (exit 6, nothing written) when none of the N steps is. The
 * output is an OBJ with the input's vertices and faces at the flowed,
 * normalized positions. Exit status: 0 written, 2 usage, 3 input
 * unreadable, 4 not a closed manifold surface without zero-area faces,
 * 5 output not written, 6 the flow failed or did not free the surface,
 * 7 out of memory, 8 interrupted. --report writes a JSON of the steps,
 * --png a picture of the input and the flowed surface side by side.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/json_write.h"
#include "base/timer.h"
#include "cli_args.h"
#include "cli_closed_surface.h"
#include "cli_unit_scale.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "cli_surface_png.h"
#include "exit_codes.h"
#include "geom/self_intersect.h"
#include "mesh/mesh_io.h"
#include "opt/cmcf.h"

#define FLOW_MAX_STEPS 100000

static void usage(FILE *out)
{
    fprintf(out,
            "usage: scaf flow IN -o OUT.obj --steps N [--delta D] [--until-free] [--report "
            "R.json]\n"
            "                 [--png P.png [--png-size N]] [--quiet]\n"
            "\n"
            "Conformalized mean curvature flow (Kazhdan, Solomon, Ben-Chen 2012) of the\n"
            "closed surface IN: it becomes rounder at every step and, after a few, free of\n"
            "self-intersections. The surface is first moved and scaled to unit area\n"
            "(area-weighted centroid at the origin); every step solves\n"
            "(M - D L) U' = M U (L: cotangent Laplacian of IN, M: barycentric mass of the\n"
            "current shape) and normalizes again. Writes the input's vertices and faces at\n"
            "the flowed positions, in that normalized frame.\n"
            "\n"
            "  -o, --output FILE  the OBJ to write (nothing is left on failure)\n"
            "  -n, --steps N      steps to run, 1..%d (with --until-free: at most N)\n"
            "  --delta D          time step, > 0 (default 1e-3)\n"
            "  --until-free       stop at the first step whose surface is free of\n"
            "                     self-intersections (exact check after every step);\n"
            "                     fail (exit 6) if none of the N steps is\n"
            "  --report FILE      a JSON report: delta, steps done, whether the result is\n"
            "                     free, and per step its seconds (with --until-free its\n"
            "                     defects: intersecting face pairs + zero-area "
            "faces)\n" CLI_SURFACE_PNG_HELP(
                "the input and the flowed surface side by side") "  -q, --quiet        "
                                                                 "no "
                                                                 "per-step lines on "
                                                                 "stderr "
                                                                 "(step, seconds, and "
                                                                 "with\n"
                                                                 "                     "
                                                                 "--until-free the "
                                                                 "intersecting face "
                                                                 "pairs)"
                                                                 "\n" CLI_OUTPUTS_HELP "\n",
            FLOW_MAX_STEPS);
    exit_codes_print(out);
}

/* The exact check of the current surface: its defects (intersecting face
 * pairs + zero-area faces; 0 = free), or -1 after printing why it could
 * not run. The text for the step line goes into what. */
static long long surface_defects(const mesh *m, char *what, size_t size, int *status)
{
    si_report r;
    scaf_error err;
    err_clear(&err);
    scaf_status st = si_check(m->nv, m->V, m->nf, m->F, &r, &err);
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf flow: self-intersection check: %s\n", err.message);
        *status = exit_code_for(st);
        return -1;
    }
    if (r.degenerate_faces > 0)
        snprintf(what, size, "%lld intersecting face pairs, %d zero-area faces", r.pairs,
                 r.degenerate_faces);
    else snprintf(what, size, "%lld intersecting face pairs", r.pairs);
    return r.pairs + r.degenerate_faces;
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
    fputs("{\n  \"input\": ", o);
    json_write_string(o, in);
    fputs(",\n  \"delta\": ", o);
    json_write_number(o, delta);
    fprintf(o, ",\n  \"until_free\": %s,\n  \"steps\": %d", until_free ? "true" : "false",
            g->steps);
    if (until_free)
        fprintf(o, ",\n  \"input_defects\": %lld,\n  \"intersection_free\": %s", g->input_defects,
                (g->steps ? g->defects[g->steps - 1] : g->input_defects) == 0 ? "true" : "false");
    fputs(",\n  \"per_step\": [", o);
    for (int s = 0; s < g->steps; s++) {
        fprintf(o, "%s\n    {\"step\": %d, \"seconds\": ", s ? "," : "", s + 1);
        json_write_number(o, g->seconds[s]);
        if (until_free) fprintf(o, ", \"defects\": %lld", g->defects[s]);
        fputc('}', o);
    }
    fputs("\n  ]\n}\n", o);
    return atomic_commit(&a, err);
}

/* Flow m->V in place; the normalized input is copied to start (NULL: not
 * kept). 0, or the exit status after printing why. */
static int run_flow(mesh *m, int steps, double delta, int until_free, int quiet, flow_log *g,
                    double *start)
{
    scaf_error err;
    err_clear(&err);
    cmcf f;
    scaf_status st = cmcf_init(&f, m->nv, m->V, m->nf, m->F, delta, &err);
    if (st == SCAF_OK) st = cmcf_normalize(m->nv, m->V, m->nf, m->F, &err);
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf flow: %s\n", err.message);
        cmcf_free(&f);
        return exit_code_for(st);
    }
    if (start) memcpy(start, m->V, sizeof(double) * 3 * (size_t)m->nv);
    int rc = EXIT_OK;
    long long defects = -1;
    char what[128] = "";
    if (until_free) {
        g->input_defects = defects = surface_defects(m, what, sizeof what, &rc);
        if (defects == 0 && !quiet)
            fprintf(stderr, "scaf flow: the input is already free of self-intersections\n");
        else if (defects > 0 && !quiet) fprintf(stderr, "scaf flow: input: %s\n", what);
    }
    for (int s = 1; s <= steps && defects != 0 && rc == EXIT_OK; s++) {
        double t0 = timer_now();
        st = cmcf_step(&f, m->V, &err);
        if (st != SCAF_OK) {
            fprintf(stderr, "scaf flow: %s\n", err.message);
            rc = exit_code_for(st);
            break;
        }
        double t_step = timer_now() - t0;
        if (until_free && (defects = surface_defects(m, what, sizeof what, &rc)) < 0) break;
        g->seconds[g->steps] = t_step;
        g->defects[g->steps++] = defects;
        if (!quiet) {
            if (until_free)
                fprintf(stderr, "scaf flow: step %d: %.3f s, check %.3f s, %s\n", s, t_step,
                        timer_now() - t0 - t_step, what);
            else fprintf(stderr, "scaf flow: step %d: %.3f s\n", s, t_step);
        }
        cli_signal_test_point(s);
        if (cli_signal_caught()) break;
    }
    int done = f.steps;
    cmcf_free(&f);
    if (rc == EXIT_OK && until_free && defects == 0 && done > 0 && !quiet)
        fprintf(stderr, "scaf flow: free of self-intersections after %d step%s\n", done,
                done > 1 ? "s" : "");
    if (rc == EXIT_OK && until_free && defects != 0 && !cli_signal_caught()) {
        fprintf(stderr,
                "scaf flow: the surface still intersects itself after %d steps (%s); nothing "
                "written\n",
                steps, what);
        rc = EXIT_NUMERIC;
    }
    return rc;
}

static int flow_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *report = NULL;
    double delta = 1e-3;
    int steps = 0, until_free = 0, quiet = 0;
    cli_surface_png png;
    cli_surface_png_init(&png);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int taken = cli_surface_png_option("flow", argc, argv, &i, &png);
        if (taken < 0) return EXIT_USAGE;
        if (taken) continue;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            CLI_NEED_VALUE("flow");
            out = v;
        } else if (!strcmp(a, "-n") || !strcmp(a, "--steps")) {
            CLI_NEED_VALUE("flow");
            if (!cli_parse_int(v, &steps)) CLI_BAD_VALUE("flow");
            if (steps < 1 || steps > FLOW_MAX_STEPS) CLI_OUT_OF_RANGE("flow", "in 1..100000");
        } else if (!strcmp(a, "--delta")) {
            CLI_NEED_VALUE("flow");
            if (!cli_parse_double(v, &delta)) CLI_BAD_VALUE("flow");
            if (!(delta > 0) || delta > 1e6) CLI_OUT_OF_RANGE("flow", "> 0 and <= 1e6");
        } else if (!strcmp(a, "--report")) {
            CLI_NEED_VALUE("flow");
            report = v;
        } else if (!strcmp(a, "--until-free")) {
            until_free = 1;
        } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
            quiet = 1;
        } else if (cli_take_input("flow", a, &in) != EXIT_OK) {
            return EXIT_USAGE;
        }
    }
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
    int e = 0;
    flow_log g = {0, malloc(sizeof(double) * (size_t)steps),
                  malloc(sizeof(long long) * (size_t)steps), -1};
    double *start = kp >= 0 ? malloc(sizeof(double) * 3 * (size_t)(m.nv > 0 ? m.nv : 1)) : NULL;
    if (!g.seconds || !g.defects || (kp >= 0 && !start)) {
        fprintf(stderr, "scaf flow: out of memory\n");
        rc = EXIT_NOMEM;
    } else if ((rc = cli_check_closed_surface("flow", in, &m, "the flow")) == EXIT_OK &&
               (rc = cli_unit_scale("flow", in, &m, &e)) == EXIT_OK) {
        /* at unit scale (tools/cli_unit_scale); the flow normalizes the
         * surface anyway, so the output needs no scaling back */
        rc = run_flow(&m, steps, delta, until_free, quiet, &g, start);
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
        surface_view panels[2] = {{m.nv, start, m.nf, m.F, NULL, 0, NULL},
                                  {m.nv, m.V, m.nf, m.F, NULL, 0, NULL}};
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
