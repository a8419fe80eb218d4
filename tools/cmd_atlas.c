/* tools/cmd_atlas: `scaf atlas IN -o OUT.obj`: multi-chart texture atlas.
 *
 * Reads the mesh, optimizes all charts together inside one scaffold
 * (app/atlas: settle, then compaction), normalizes the layout with one
 * uniform scale into the unit square, verifies the result with the exact
 * checker (bijective) and the chart-gap measure (>= padding), and only
 * then writes the OBJ (original `v` lines, new `vt` + `f v/vt`)
 * atomically; optional JSON report and SVG / PNG pictures. Bad input gives a
 * message and the exit status of tools/exit_codes.h, and no output file.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app/atlas.h"
#include "app/atlas_output.h"
#include "app/atlas_report.h"
#include "app/seam_report.h"
#include "app/stop_reason.h"
#include "base/timer.h"
#include "cli_args.h"
#include "cli_png.h"
#include "cli_progress.h"
#include "cli_seams.h"
#include "cli_mesh_io.h"
#include "cli_outputs.h"
#include "cli_signal.h"
#include "cli_threads.h"
#include "cli_uv_job.h"
#include "exit_codes.h"
#include "geom/bijectivity.h"
#include "geom/chart_gap.h"
#include "mesh/mesh_io.h"

/* The default padding: 4 texels of a 1024 texture (0.00390625). */
#define DEFAULT_RESOLUTION 1024.0
#define DEFAULT_PADDING_TEXELS 4.0

static void usage(FILE *o)
{
    fprintf(o,
            "usage: scaf atlas IN -o OUT.obj [options]\n"
            "\n"
            "Builds a texture atlas: every chart (UV chart cut along the input's UV seams,\n"
            "or an automatic chart, see --seams) is optimized together with all the\n"
            "others inside one scaffold (no two charts can ever overlap), re-placed rigidly\n"
            "by a raster packer (kept only when proved bijective), compacted by SCAF\n"
            "iterations with a contracting scaffold, and scaled uniformly into the unit UV\n"
            "square. The map is bijective after every iteration; the padding is kept by\n"
            "the line search and proved exactly (exact arithmetic on the written numbers)\n"
            "before the file is written.\n"
            "Automatic charts (a mesh without vt, or vt that do not cut it into disks):\n"
            "the surface is segmented (mesh/chart_segment) and every chart that is not a\n"
            "disk, possibly with holes, is cut open (handle loops; a closed piece along a\n"
            "tree of short seams through its points of highest curvature): any manifold\n"
            "mesh, closed or open, of any genus, with or without vt (docs/seams.md).\n"
            "\n"
            "IN: OBJ (.obj), OFF (.off) or PLY (.ply, ASCII or binary), each optionally\n"
            "gzip-compressed (.gz); an unknown extension is recognized by the content;\n"
            "\"-\" reads the standard input (format: --input-format, or the first bytes).\n"
            "Polygons are fan-triangulated. UVs: OBJ vt; PLY face texcoord lists or vertex\n"
            "s,t / u,v / texture_u,texture_v. -o OUT.ply writes a binary PLY with a\n"
            "texcoord list per face (the corners of a seam differ).\n"
            "\n");
    fprintf(o,
            "options:\n"
            "  -o, --output FILE        output OBJ (required)\n"
            "  --seams S                where the charts are cut: input (the vt seams; each\n"
            "                           chart must be a disk, possibly with holes), auto\n"
            "                           (automatic charts, the vt ignored), extend (the vt\n"
            "                           seams plus cuts where a chart is not a disk);\n"
            "                           default: input when the vt cut the mesh into disks,\n"
            "                           else auto\n"
            "  --max-distortion E       split every chart whose settled E exceeds E in two\n"
            "                           along its normal cones, round by round (default 4.2\n"
            "                           for automatic seams, off for input seams; 0: never);\n"
            "                           automatic seams: neighbours whose union settles\n"
            "                           below 4 + 3/4 (E - 4) and fills its box as well are\n"
            "                           then joined\n"
            "  --split-charts           split the chart filling least of its least-area box\n"
            "                           while below 0.45, one a round (default for automatic\n"
            "                           seams; --no-split-charts: never)\n"
            "  --chart-groups           the output OBJ groups each chart's faces under\n"
            "                           `g chart_N` (N as in --report's face_chart), in\n"
            "                           place of the input's `g` lines\n"
            "  --png-seams FILE         the 3D surface from the front and from the back,\n"
            "                           each chart in its --png colour, seams drawn dark,\n"
            "                           beside the packed atlas in the same colours\n");
    fprintf(o,
            "  --padding P              minimum distance between two charts, in units of the\n"
            "                           unit square (default K / R below: 4 / 1024 =\n"
            "                           0.00390625; --padding 0: charts only never overlap)\n"
            "  --resolution R           texture size in texels (default 1024); the padding is\n"
            "                           K / R unless --padding is given\n"
            "  --padding-texels K       padding in texels of that texture (default 4)\n"
            "  --init NAME              tutte (default), harmonic, mvc (mean-value), or\n"
            "                           input: start from the input UVs, only when the\n"
            "                           exact checker proves them bijective\n"
            "  --iterations N           cap of the settling iterations (default 200; settling\n"
            "                           runs SLIM then Newton to convergence: until the\n"
            "                           estimated relative distance of E to its minimum is\n"
            "                           below 1e-4, as scaf param's --tolerance)\n"
            "  --compact-iterations N   cap of the compaction iterations (default 150;\n"
            "                           0 = no compaction)\n"
            "  --distortion-tolerance T stop compacting when E exceeds (1+T) times the settled\n"
            "                           E (default 0.05); the best packed layout within it is\n"
            "                           kept (`scaf edit`'s compact: the same rule, 0.05)\n");
    /* (two strings: C caps a string literal at 4095 characters) */
    fprintf(o,
            "  --box-scale S            scaffold box while settling (default 3)\n"
            "  --lambda-ratio R         scaffold weight ratio (default 0.01)\n"
            "  --compact-lambda-ratio R scaffold weight ratio while compacting (default 1:\n"
            "                           fewer iterations; 0.3 keeps E lower, packs slower)\n"
            "  --no-rotate              turn charts by multiples of 45 degrees only (default:\n"
            "                           also to their least-area box, and the layout to its\n"
            "                           smallest bounding square)\n"
            "  --quiet                  no progress line\n"
            "  --input-format F         obj, off, ply, gltf or glb: the input's format\n"
            "                           whatever its name (default: the extension, or for\n"
            "                           \"-\" (standard input) the first bytes)\n"
            "  --uv-set N               glTF: the TEXCOORD_N read and written (default 0)\n"
            "  --threads N              threads of the per-triangle work (assembly, line\n"
            "                           search) and of the solver's dense kernels (default:\n"
            "                           all cores, or OPENBLAS_NUM_THREADS when set); the\n"
            "                           same N gives the same bytes\n"
            "  --deterministic          the same bytes for any --threads N (the\n"
            "                           factorization's tree cut into 4 bins whatever N;\n"
            "                           slower, most with one thread)\n"
            "  --report FILE.json       per-iteration energy, gap and packing efficiency,\n"
            "                           before/after compaction, per-chart distortion\n"
            "  --svg FILE               picture of the atlas, charts in distinct colours\n"
            "  --png FILE               the same picture as a PNG of the unit UV square\n"
            "                           (transparent outside the charts, chart boundaries\n"
            "                           outlined), its border, chart numbers and, below it,\n"
            "                           the padding's length\n"
            "  --png-plain              the PNG without border, numbers and legend: exactly\n"
            "                           the unit square, a texture\n"
            "  --png-size N             pixels of the PNG's side (16..16384, default 1024)\n"
            "  --checker [N]            PNG only (the SVG has none): shade the fill with a\n"
            "                           checkerboard on the 3D surface, N squares across the\n"
            "                           bounding-box diagonal (default 20); stretched or\n"
            "                           sheared squares show the distortion\n"
            "  -h, --help               this text\n"
            "\n"
            "Stopping: settling ends at the first of: --iterations done (iteration_limit);\n"
            "E decreased by less than 1e-3 relatively in one iteration (tolerance); no\n"
            "step lowers the energy (zero_step); no new low of E in 10 iterations\n"
            "(noise_floor). Compaction (only with two or more charts)\n"
            "ends at the first of: --compact-iterations done (iteration_limit); E above\n"
            "the distortion tolerance (distortion_limit); the layout's side shrank by\n"
            "less than 0.15%% over 4 iterations (packing_stalled); three iterations in a\n"
            "row without a step (zero_step). The reason is printed at the end (stop\n"
            "reason) and in the report (stop_reason, phase_stop_reasons).\n");
    fputs(CLI_OUTPUTS_HELP "\n", o);
    exit_codes_print(o);
}

typedef struct progress_state {
    cli_progress bar;
    const atlas_options *opt; /* the phases' caps and tolerances */
    int settled;              /* settle iterations seen */
    atlas_iteration *it;
    int n, size;
} progress_state;

/* The bar's phase after iteration it: settle until atlas_run's settle
 * rule ends it (app/atlas.c), then the packer, then compaction. */
static void progress_phase(progress_state *s, const atlas_iteration *it)
{
    const atlas_options *o = s->opt;
    if (it->phase == ATLAS_SETTLE) {
        s->settled++;
        int end = s->settled >= o->settle_iterations || it->info.step == 0.0 ||
            (o->settle_tolerance > 0.0 && it->info.criterion < o->settle_tolerance);
        cli_progress_step(&s->bar, s->settled, it->info.energy, it->info.criterion, NULL);
        if (end) cli_progress_phase(&s->bar, o->repack ? "pack" : "compact", 0, 0, 0.0);
        return;
    }
    int k = s->n - s->settled;
    if (k == 1) cli_progress_phase(&s->bar, "compact", o->compact_iterations, 0, 0.0);
    char extra[64];
    snprintf(extra, sizeof extra, "efficiency %.3f", it->efficiency);
    cli_progress_step(&s->bar, k, it->info.energy, NAN, extra);
}

static int on_iteration(const atlas *a, const atlas_iteration *it, void *user)
{
    (void)a;
    progress_state *s = user;
    if (s->n == s->size) {
        int size = s->size ? 2 * s->size : 64;
        atlas_iteration *p = realloc(s->it, sizeof *p * (size_t)size);
        if (!p) return 0;
        s->it = p;
        s->size = size;
    }
    s->it[s->n++] = *it;
    cli_signal_test_point(s->n);
    if (cli_signal_caught()) return 1; /* SIGINT / SIGTERM: stop after this iteration */
    progress_phase(s, it);
    return 0;
}

/* --png: face f in its chart's colour (ctx: the atlas) */
static unsigned chart_colour(int f, const void *ctx)
{
    return atlas_chart_colour(((const atlas *)ctx)->chart[f]);
}

static int atlas_main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *report = NULL, *svg = NULL, *png_seams = NULL;
    int chart_groups = 0;
    int quiet = 0, threads = 0; /* threads 0: the default (cli_threads_apply) */
    double resolution = 0.0, texels = -1.0, padding = -1.0;
    atlas_options opt = atlas_options_default();
    cli_png png;
    cli_png_init(&png, 1);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        int pr = cli_png_option("atlas", argc, argv, &i, &png);
        if (pr == 0) pr = cli_input_format_option("atlas", argc, argv, &i);
        if (pr < 0) return EXIT_USAGE;
        if (pr > 0) continue;
#define NEED_VALUE() CLI_NEED_VALUE("atlas")
#define BAD_VALUE() CLI_BAD_VALUE("atlas")
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return EXIT_OK;
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            NEED_VALUE();
            out = v;
        } else if (!strcmp(a, "--padding")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &padding)) BAD_VALUE();
            if (padding < 0) CLI_OUT_OF_RANGE("atlas", "0 or in [2^-200, 0.5)");
        } else if (!strcmp(a, "--resolution")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &resolution)) BAD_VALUE();
            if (!(resolution >= 1)) CLI_OUT_OF_RANGE("atlas", ">= 1 (texels)");
        } else if (!strcmp(a, "--padding-texels")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &texels)) BAD_VALUE();
            if (texels < 0) CLI_OUT_OF_RANGE("atlas", ">= 0");
        } else if (!strcmp(a, "--init")) {
            NEED_VALUE();
            if (!strcmp(v, "tutte")) opt.base.init = SCAF_INIT_TUTTE;
            else if (!strcmp(v, "harmonic")) opt.base.init = SCAF_INIT_HARMONIC;
            else if (!strcmp(v, "mvc")) opt.base.init = SCAF_INIT_MVC;
            else if (!strcmp(v, "input")) opt.init_input = 1;
            else BAD_VALUE();
        } else if (!strcmp(a, "--iterations")) {
            NEED_VALUE();
            if (!cli_parse_int(v, &opt.settle_iterations)) BAD_VALUE();
        } else if (!strcmp(a, "--compact-iterations")) {
            NEED_VALUE();
            if (!cli_parse_int(v, &opt.compact_iterations)) BAD_VALUE();
        } else if (!strcmp(a, "--distortion-tolerance")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &opt.distortion_tolerance)) BAD_VALUE();
        } else if (!strcmp(a, "--box-scale")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &opt.base.box_scale)) BAD_VALUE();
        } else if (!strcmp(a, "--compact-lambda-ratio")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &opt.compact_lambda_ratio)) BAD_VALUE();
        } else if (!strcmp(a, "--max-distortion")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &opt.max_distortion)) BAD_VALUE();
            if (!(opt.max_distortion == 0.0 || opt.max_distortion > 4.0))
                CLI_OUT_OF_RANGE("atlas", "> 4 (4 is an isometry), or 0: never split");
        } else if (!strcmp(a, "--split-charts")) {
            opt.split_charts = 1;
        } else if (!strcmp(a, "--no-split-charts")) {
            opt.split_charts = 0;
        } else if (!strcmp(a, "--chart-groups")) {
            chart_groups = 1;
        } else if (!strcmp(a, "--lambda-ratio")) {
            NEED_VALUE();
            if (!cli_parse_double(v, &opt.base.lambda_ratio)) BAD_VALUE();
        } else if (!strcmp(a, "--seams")) {
            NEED_VALUE();
            if (!cli_seams_parse(v, &opt.base.seams)) BAD_VALUE();
        } else if (!strcmp(a, "--png-seams")) {
            NEED_VALUE();
            png_seams = v;
        } else if (!strcmp(a, "--no-rotate")) {
            opt.rotate = 0;
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            quiet = 1;
        } else if (!strcmp(a, "--threads")) {
            NEED_VALUE();
            if (!cli_parse_int(v, &threads)) BAD_VALUE();
            if (threads < 1) CLI_OUT_OF_RANGE("atlas", ">= 1");
        } else if (!strcmp(a, "--deterministic")) {
            scaf_set_deterministic(1);
        } else if (!strcmp(a, "--report")) {
            NEED_VALUE();
            report = v;
        } else if (!strcmp(a, "--svg")) {
            NEED_VALUE();
            svg = v;
        } else if (cli_take_input("atlas", a, &in) != EXIT_OK) {
            return EXIT_USAGE;
        }
#undef NEED_VALUE
#undef BAD_VALUE
    }
    if (!in || !out) {
        fprintf(stderr, "scaf atlas: %s (see --help)\n",
                !in ? "no input file" : "no output file: use -o OUT.obj");
        return EXIT_USAGE;
    }
    if (cli_png_finish("atlas", &png) < 0) return EXIT_USAGE;
    /* The padding is --padding P, or K texels of an R-texel texture:
     * --padding-texels K (default 4) at --resolution R (default 1024), so
     * mip levels of a baked texture do not bleed between charts;
     * --padding 0 asks for none. */
    if (texels >= 0.0 && padding >= 0.0) {
        fprintf(stderr, "scaf atlas: give either --padding or --padding-texels, not both\n");
        return EXIT_USAGE;
    }
    if (padding < 0.0) {
        if (!(resolution > 0.0)) resolution = DEFAULT_RESOLUTION;
        if (texels < 0.0) texels = DEFAULT_PADDING_TEXELS;
        padding = texels / resolution;
    }
    opt.padding = padding;
    /* every range, before any work (the library's own check) */
    char msg[256];
    if (atlas_options_check(&opt, msg, sizeof msg) != SCAF_OK) {
        if (texels >= 0.0)
            fprintf(stderr, "scaf atlas: %s (--padding-texels %g / --resolution %g)\n", msg, texels,
                    resolution);
        else fprintf(stderr, "scaf atlas: %s\n", msg);
        return EXIT_USAGE;
    }
    cli_threads_apply(threads);
    /* every output checked before any work; written all together at the end */
    double t_start = timer_now();
    cli_uv_job job;
    cli_uv_job_paths paths = {out, svg, png.path, report, NULL, NULL, png_seams};
    mesh m;
    int read_rc = cli_uv_job_start(&job, "atlas", in, &paths, quiet, &m);
    if (read_rc != EXIT_OK) return read_rc;
    scaf_error err;
    err_clear(&err);
    int rc = EXIT_OK;
    atlas a;
    progress_state ps = {0};
    double *UV = NULL;
    seam_edges seams = {0};
    ps.opt = &opt;
    cli_progress_init(&ps.bar, "atlas", quiet);
    cli_progress_phase(&ps.bar, "segment", 0, 0, 0.0);
    scaf_status st = atlas_init(&a, &m, &opt, &err);
    cli_progress_clear(&ps.bar);
    if (st == SCAF_ERR_CANCELLED && cli_signal_report("atlas")) { /* during the setup */
        mesh_free(&m);
        return EXIT_CANCELLED;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf atlas: %s: %s\n", in, err.message);
        mesh_free(&m);
        return exit_code_for(st);
    }
    double setup = timer_now() - t_start;
    if (cli_seams_report("atlas", &m, a.Fw, a.seams_used, a.seams_why, a.ncharts, quiet, &seams)) {
        rc = EXIT_NOMEM;
        goto done;
    }
    if (!quiet && !cli_progress_live(&ps.bar))
        fprintf(stderr, "scaf atlas: %s: %d faces, %d chart(s)%s, padding %g\n", in, m.nf,
                a.ncharts, a.split_uvs ? " (pinched vt split)" : "", opt.padding);
    if (cli_signal_report("atlas")) {
        rc = EXIT_CANCELLED;
        goto done;
    }
    cli_progress_phase(&ps.bar, "settle", opt.settle_iterations, !(opt.settle_tolerance > 0),
                       opt.settle_tolerance);
    st = atlas_run(&a, on_iteration, &ps, &err);
    cli_progress_done(&ps.bar, NULL);
    if (cli_signal_report("atlas")) {
        rc = EXIT_CANCELLED;
        goto done;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf atlas: %s: %s\n", in, err.message);
        rc = exit_code_for(st);
        goto done;
    }

    /* ---- normalize and verify before writing ---------------------------- */
    UV = malloc(sizeof(double) * 2 * (size_t)a.nw);
    if (!UV) {
        fprintf(stderr, "scaf atlas: out of memory\n");
        rc = EXIT_NOMEM;
        goto done;
    }
    /* bijective and padding certified exactly on the doubles written */
    atlas_output ao;
    st = atlas_output_verify(&a, UV, &ao, &err);
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf atlas: %s; nothing written\n", err.message);
        rc = st == SCAF_ERR_NOMEM ? EXIT_NOMEM : EXIT_INTERNAL;
        goto done;
    }
    double gap = ao.gap, eff = ao.efficiency;
    /* the figure users compare (docs/energy.md): atlas_energy is at the
     * layout's scale before it was shrunk into the unit square */
    double e_matched = NAN;
    scaf_area_matched_energy(m.V, m.nv, m.F, m.nf, UV, a.nw, a.Fw, &e_matched);
    mesh o = {m.nv, m.V, m.nf, m.F, a.nw, UV, a.Fw};
    if (chart_groups) job.face_group = a.chart;
    if ((rc = cli_uv_job_write_map(&job, &o)) != EXIT_OK) goto done;
    cli_gltf_pieces_report("atlas", in, &job.rinfo, quiet, &o);
    const char *path;
    if (svg) {
        char title[256];
        snprintf(title, sizeof title,
                 "%s: %d charts, packing efficiency %.3f, min gap %.4f, E = %.4f (area-matched)",
                 in, a.ncharts, eff, gap, e_matched);
        path = cli_outputs_begin(&job.outs, job.k.svg, &err);
        st = path ? atlas_svg_write(path, &a, UV, title, &err) : SCAF_ERR_IO;
        if ((rc = cli_outputs_end(&job.outs, job.k.svg, st, &err)) != EXIT_OK) goto done;
    }
    if (!png.plain) {
        png.opt.chart = a.chart;       /* the charts' numbers */
        png.opt.padding = opt.padding; /* the legend's padding bar */
        png.opt.frame = 1;             /* the unit square's border */
    }
    if (png.path &&
        (rc = cli_uv_job_png(&job, a.nw, UV, a.nf, a.Fw, chart_colour, &a, m.nv, m.V, m.F,
                             &png.opt)) != EXIT_OK)
        goto done;
    double total = timer_now() - t_start;
    if ((rc = cli_seams_png(&job.outs, job.png_seams, &m, a.chart, &seams, &o)) != EXIT_OK)
        goto done;
    if (report) {
        seam_report sr = {a.seams_used, a.seams_why, a.ncharts, a.nf, a.chart, &seams, NULL, 0};
        gltf_piece *pieces = NULL; /* a glTF input: which primitive went where */
        cli_gltf_pieces_load("atlas", in, &job.rinfo, quiet, &pieces, &sr.npieces);
        sr.pieces = pieces;
        atlas_report r = {in,  out, &a,        resolution, setup, total,
                          gap, eff, e_matched, ps.n,       ps.it, &sr};
        path = cli_outputs_begin(&job.outs, job.k.report, &err);
        st = path ? atlas_report_write(path, &r, &err) : SCAF_ERR_IO;
        free(pieces);
        if ((rc = cli_outputs_end(&job.outs, job.k.report, st, &err)) != EXIT_OK) goto done;
    }
    rc = cli_outputs_commit(&job.outs);
    if (rc == EXIT_OK && !quiet) {
        fprintf(stderr,
                "scaf atlas: %d charts, %d+%d iterations, E %.5f (area-matched), packing "
                "efficiency "
                "%.3f -> %.3f, min chart gap %.5f, %.2f s\n",
                a.ncharts, a.settle_done, a.compact_done, e_matched, a.eff_before, eff, gap, total);
        scaf_stop_reason why = atlas_stop_reason(&a);
        fprintf(stderr, "scaf atlas: stop reason: %s (%s; settle: %s, compact: %s)\n",
                scaf_stop_reason_name(why), stop_reason_explained(why),
                scaf_stop_reason_name(a.settle_stop), scaf_stop_reason_name(a.compact_stop));
    }
done:
    cli_outputs_abort(&job.outs);
    seam_edges_free(&seams);
    free(UV);
    free(ps.it);
    atlas_free(&a);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_atlas(int argc, char **argv) { return cli_signal_run(atlas_main, argc, argv); }
