/* tools/cmd_param: `scaf param IN -o OUT.obj`: bijective UV parametrization.
 *
 * A thin layer over the scaf_param_* API: reads the mesh, runs SCAF with
 * a live progress line on stderr (when it is a terminal), writes the OBJ
 * (original `v` lines, new `vt` + `f v/vt`) atomically, and optionally an
 * SVG / PNG picture and a JSON report. Bad input gives a message and the exit
 * status of tools/exit_codes.h, and no output file.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app/param.h"
#include "app/param_report.h"
#include "app/seam_report.h"
#include "geom/chart_gap.h"
#include "app/stop_reason.h"
#include "app/uv_svg.h"
#include "base/timer.h"
#include "cli_energy.h"
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
#include "mesh/mesh_io.h"
#include "scaf/scaf.h"

static void about(FILE *o)
{
    fputs("Computes a bijective, low-distortion UV map (no flipped triangle, no overlap)\n"
          "with SCAF and writes the mesh as OBJ with `vt` and `f v/vt` (the `v` lines are\n"
          "kept). Charts: the pieces of the mesh cut along its UV seams, or the connected\n"
          "components of a mesh without UVs. A chart that is not a disk (possibly with\n"
          "holes) is cut open automatically (see --seams): handles along a shortest system\n"
          "of loops, a closed piece along a tree of short seams through its points of\n"
          "highest curvature, so any manifold mesh, closed or not, of any genus, gets one\n"
          "chart per component (docs/seams.md).\n"
          "\n",
          o);
    fputs("IN: OBJ (.obj), OFF (.off) or PLY (.ply, ASCII or binary), each optionally\n"
          "gzip-compressed (.gz); an unknown extension is recognized by the content;\n"
          "\"-\" reads the standard input (format: --input-format, or the first bytes).\n"
          "Polygons are fan-triangulated. UVs: OBJ vt; PLY face texcoord lists or vertex\n"
          "s,t / u,v / texture_u,texture_v. -o OUT.ply writes a binary PLY with a\n"
          "texcoord list per face (the corners of a seam differ).\n"
          "\n",
          o);
}

static void after(FILE *o)
{
    fputc('\n', o);
    cli_energy_help(o);
    fputs("\n"
          "The energy E reported is sum_f A_f (|J_f|^2 + |J_f^-1|^2) / sum_f A_f over the\n"
          "mesh triangles (A_f: 3D area); 4 at an isometry.\n"
          "\n"
          "Stopping: the run ends at the first of: --iterations done (iteration_limit);\n"
          "the tolerance test above (converged; one slow iteration never ends the run);\n"
          "no step lowers the energy any more, also with --tolerance 0 (zero_step:\n"
          "converged to floating-point precision, more iterations would not change the\n"
          "map). The reason and the last criterion are printed at the end (stop reason)\n"
          "and in the report (stop_reason, final_criterion, per iteration criterion).\n",
          o);
    fputs(CLI_OUTPUTS_HELP "\n", o);
    exit_codes_print(o);
}

/* --seams S (tools/cli_seams) into the scaf_options_t at o->dest */
/* --energy: a name (or alias) of the library's list of energies */
static int take_energy(const char *cmd, const cli_option *o, const char *v)
{
    if (cli_energy_parse(v, o->dest)) return EXIT_OK;
    const char *names[64];
    int n = 0;
    for (int e = 0; e < scaf_energy_count() && n < 63; e++) {
        scaf_energy_info_t in;
        if (scaf_energy_info(e, &in) == SCAF_OK) names[n++] = in.name;
    }
    names[n] = NULL;
    int k = 0;
    cli_option e = *o;
    e.kind = CLI_OPT_ENUM; /* not one of them: the common wording */
    e.choices = names;
    e.dest = &k;
    (void)cli_option_apply(cmd, &e, v); /* prints the error */
    return EXIT_USAGE;
}

static int take_seams(const char *cmd, const cli_option *o, const char *v)
{
    static const char *const names[] = {"input", "auto", "extend", NULL};
    scaf_options_t *opt = o->dest;
    if (cli_seams_parse(v, &opt->seams)) return EXIT_OK;
    int k = 0;
    cli_option e = *o;
    e.kind = CLI_OPT_ENUM; /* not one of them: the common wording */
    e.choices = names;
    e.dest = &k;
    (void)cli_option_apply(cmd, &e, v); /* prints the error */
    return EXIT_USAGE;
}

typedef struct progress_state {
    const scaf_param_t *p;
    int verify;        /* check bijectivity after every iteration */
    int not_bijective; /* iteration at which the check failed, 0 if none */
    cli_progress bar;
    scaf_iteration_info_t *it;
    int n, size;
    int oom;
    double criterion; /* of the last iteration (INFINITY before any) */
} progress_state;

static int on_iteration(const scaf_iteration_info_t *info, void *user)
{
    progress_state *s = user;
    if (s->n == s->size) {
        int size = s->size ? 2 * s->size : 64;
        scaf_iteration_info_t *p = realloc(s->it, sizeof *p * (size_t)size);
        if (!p) {
            s->oom = 1;
            return 0;
        }
        s->it = p;
        s->size = size;
    }
    s->it[s->n++] = *info;
    s->criterion = info->criterion;
    cli_signal_test_point(info->iteration);
    if (cli_signal_caught()) return 1; /* SIGINT / SIGTERM: stop after this iteration */
    if (s->verify) {
        param_map pm;
        param_working_map(s->p, &pm);
        bij_report rep;
        if (bij_check(pm.nuv, pm.uv, pm.nf, pm.FT, NULL, NULL, &rep, NULL) != SCAF_OK ||
            !rep.bijective) {
            s->not_bijective = info->iteration;
            return 1;
        }
    }
    cli_progress_step(&s->bar, info->iteration, info->energy, info->criterion, NULL);
    return 0;
}

/* The command line of `scaf param`. */
typedef struct param_args {
    const char *in, *out, *report, *svg, *png_seams;
    int quiet, svg_scaffold, verify;
    int threads; /* --threads N, 0 = the default (cli_threads_apply) */
    scaf_options_t opt;
    cli_png png;
} param_args;

/* parse_args returns this to go on, or the exit status to end with. */
enum { PARSED_RUN = -1 };

/* Parse and check the arguments into *o (usage errors printed). */
static int parse_args(int argc, char **argv, param_args *o)
{
    memset(o, 0, sizeof *o);
    o->opt = scaf_options_default();
    cli_png_init(&o->png, 0);
    static const char *const solvers[] = {"auto", "slim", "newton", NULL};
    static const int solver_values[] = {SCAF_SOLVER_AUTO, SCAF_SOLVER_SLIM, SCAF_SOLVER_NEWTON};
    static const char *const inits[] = {"tutte", "harmonic", "mvc", NULL};
    static const int init_values[] = {SCAF_INIT_TUTTE, SCAF_INIT_HARMONIC, SCAF_INIT_MVC};
    int solver = (int)o->opt.solver, init = (int)o->opt.init;
    int deterministic = 0;
    /* the ranges of the library's options: param_options_check (below) */
    const cli_option options[] = {
        CLI_GROUP("options:"),
        CLI_STRING("output", 'o', &o->out, "FILE", "output OBJ (required)"),
        CLI_INT("iterations", 0, &o->opt.max_iterations, "N", 0, 100000000,
                "iteration cap (default 200)"),
        CLI_DOUBLE("tolerance", 0, &o->opt.tolerance, "T", 0, 0,
                   "converged when the estimated relative distance of the energy to its "
                   "minimum, (E - E_min) / E, is below T: the larger of the last Newton "
                   "decrement and the linear tail d rho / (1 - rho) of the last decreases d "
                   "(rho: their largest ratio over 3 iterations), judged from the 4th iteration "
                   "on (default 1e-5; 0 = no test, see Stopping); arap, whose minimum can be 0: "
                   "(E - E_min) / (E + 1), E per unit of area"),
        CLI_ENUM("solver", 0, &solver, "NAME", solvers,
                 "auto (default: SLIM until one iteration lowers the objective by less than "
                 "1e-2 relatively, then projected Newton), slim, or newton (from the start); for "
                 "every --energy",
                 .values = solver_values),
        CLI_CALLBACK("energy", 0, take_energy, &o->opt.energy, "NAME",
                     "the charts' distortion energy (default symmetric-dirichlet; the list: "
                     "energies, below)"),
        CLI_ENUM("init", 0, &init, "NAME", inits, "mvc (mean-value, default), harmonic, or tutte",
                 .values = init_values),
        CLI_CALLBACK("seams", 0, take_seams, &o->opt, "S",
                     "where the charts are cut: input (the vt seams; each chart must be a disk, "
                     "possibly with holes), auto (automatic seams, the vt ignored), extend (the vt "
                     "seams plus cuts where a chart is not a disk); default: input when the vt "
                     "cut the mesh into disks, else auto"),
        CLI_STRING("png-seams", 0, &o->png_seams, "FILE",
                   "the 3D surface from the front and from the back, each chart in its own "
                   "colour, the seams drawn dark"),
        CLI_DOUBLE("box-scale", 0, &o->opt.box_scale, "S", 0, 0,
                   "scaffold box = S times the UV bounding box (default 3)"),
        CLI_DOUBLE("lambda-ratio", 0, &o->opt.lambda_ratio, "R", 0, 0,
                   "scaffold weight lambda = R * E_M / |S| (default 0.01; a tenth of it in "
                   "Newton iterations; arap: E_M + the 3D area, since E_M is about 0 at its "
                   "minimum)"),
        CLI_DOUBLE("min-angle", 0, &o->opt.min_angle_deg, "DEG", 0, 0,
                   "scaffold minimum angle (default 20)"),
        CLI_FLAG("quiet", 'q', &o->quiet, "no progress line"),
        CLI_INPUT_FORMAT_OPTIONS,
        CLI_INT("threads", 0, &o->threads, "N", 1, INT_MAX,
                "threads of the per-triangle work (assembly, line search) and of the solver's "
                "dense kernels (default: all cores, or OPENBLAS_NUM_THREADS when set); the same "
                "N gives the same bytes"),
        CLI_FLAG("deterministic", 0, &deterministic,
                 "the same bytes for any --threads N (the factorization's tree cut into 4 bins "
                 "whatever N; slower, most with one thread)"),
        CLI_STRING("report", 0, &o->report, "FILE.json",
                   "options, per-iteration energy and time, phase split"),
        CLI_STRING("svg", 0, &o->svg, "FILE", "picture of the UV layout shaded by distortion"),
        CLI_FLAG("svg-scaffold", 0, &o->svg_scaffold, "also draw the scaffold in the picture"),
        CLI_PNG_OPTIONS(&o->png,
                        "the same picture (without scaffold) as PNG: triangles shaded by "
                        "distortion, chart boundaries outlined, transparent outside the charts, "
                        "the colour bar of the distortion scale below (docs/param.md)"),
        CLI_FLAG("png-plain", 0, &o->png.plain, "the PNG without the colour bar"),
        CLI_FLAG("verify", 0, &o->verify,
                 "prove the map bijective with the exact checker after every iteration (stops "
                 "with exit 70 if it ever is not)"),
        CLI_OPTION_HELP,
        {0}};
    const cli_command_options cmd = {.cmd = "param",
                                     .usage = "usage: scaf param IN -o OUT.obj [options]\n\n",
                                     .about = about,
                                     .after = after,
                                     .options = options,
                                     .positionals = &o->in,
                                     .max_positionals = 1,
                                     .positional_name = "input"};
    int parsed = cli_options_parse(&cmd, argc, argv);
    if (parsed != CLI_OPTIONS_OK) return cli_options_done(&cmd, parsed);
    o->opt.solver = (scaf_solver)solver;
    o->opt.init = (scaf_init)init;
    if (deterministic) scaf_set_deterministic(1);
    if (!o->in || !o->out) {
        fprintf(stderr, "scaf param: %s (see --help)\n",
                !o->in ? "no input file" : "no output file: use -o OUT.obj");
        return EXIT_USAGE;
    }
    if (cli_png_finish("param", &o->png) < 0) return EXIT_USAGE;
    char msg[256];
    if (param_options_check(&o->opt, msg, sizeof msg) != SCAF_OK) {
        fprintf(stderr, "scaf param: %s\n", msg);
        return EXIT_USAGE;
    }
    return PARSED_RUN;
}

/* --png: the SVG's colour of face f's energy (ctx: the energies) */
static unsigned energy_colour(int f, const void *ctx)
{
    return uv_svg_colour(((const double *)ctx)[f]);
}

static int param_main(int argc, char **argv)
{
    param_args args;
    int parsed = parse_args(argc, argv, &args);
    if (parsed != PARSED_RUN) return parsed;
    cli_threads_apply(args.threads);
    const char *in = args.in, *out = args.out, *report = args.report, *svg = args.svg;
    int quiet = args.quiet, svg_scaffold = args.svg_scaffold, verify = args.verify;
    scaf_options_t opt = args.opt;
    cli_png png = args.png;
    double t_start = timer_now();
    /* every output checked before any work; written all together at the end */
    cli_uv_job job;
    cli_uv_job_paths paths = {out, svg, png.path, report, NULL, NULL, args.png_seams};
    mesh m;
    int read_rc = cli_uv_job_start(&job, "param", in, &paths, quiet, &m);
    if (read_rc != EXIT_OK) return read_rc;
    scaf_error err;
    err_clear(&err);
    int rc = EXIT_OK;
    scaf_param_t *p = scaf_param_new(&opt);
    progress_state ps = {0};
    ps.criterion = INFINITY;
    double *UV = NULL;
    int *FT = NULL;
    int *fc = NULL, nc = 0; /* chart of every face, for --png-seams and --report */
    seam_edges seams = {0};
    if (!p) {
        fprintf(stderr, "scaf param: out of memory\n");
        mesh_free(&m);
        return EXIT_NOMEM;
    }
    scaf_status st = mesh_has_uv(&m)
        ? scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, m.UV, m.nuv, m.FT)
        : scaf_param_set_mesh(p, m.V, m.nv, m.F, m.nf, NULL, 0, NULL);
    if (st == SCAF_ERR_CANCELLED && cli_signal_report("param")) { /* during the setup */
        rc = EXIT_CANCELLED;
        goto done;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf param: %s: %s\n", in, scaf_param_error(p));
        rc = st == SCAF_ERR_USAGE ? EXIT_MESH : exit_code_for(st);
        goto done;
    }
    double setup = timer_now() - t_start;
    double e0 = scaf_param_energy(p);
    ps.p = p;
    ps.verify = verify;
    cli_progress_init(&ps.bar, "param", quiet);
    if (!quiet && !cli_progress_live(&ps.bar))
        fprintf(stderr, "scaf param: %s: %d faces, %d chart(s), initial E = %.6f\n", in, m.nf,
                scaf_param_chart_count(p), e0);
    {
        param_map pm;
        param_working_map(p, &pm);
        if (cli_seams_report("param", &m, pm.FT, scaf_param_seams_used(p), param_seams_why(p),
                             scaf_param_chart_count(p), quiet, &seams)) {
            rc = EXIT_NOMEM;
            goto done;
        }
    }
    if (cli_signal_report("param")) {
        rc = EXIT_CANCELLED;
        goto done;
    }
    /* the cap is a real count only without a tolerance */
    cli_progress_phase(&ps.bar, "optimize", opt.max_iterations, !(opt.tolerance > 0),
                       opt.tolerance);
    st = scaf_param_run(p, opt.max_iterations, on_iteration, &ps);
    cli_progress_done(&ps.bar, NULL);
    if (cli_signal_report("param")) {
        rc = EXIT_CANCELLED;
        goto done;
    }
    if (ps.not_bijective) {
        fprintf(stderr,
                "scaf param: %s: BUG: the map is not bijective after iteration %d (please "
                "report)\n",
                in, ps.not_bijective);
        rc = EXIT_INTERNAL;
        goto done;
    }
    if (st != SCAF_OK) {
        fprintf(stderr, "scaf param: %s: %s\n", in, scaf_param_error(p));
        rc = exit_code_for(st);
        goto done;
    }
    double e1 = scaf_param_energy(p);
    int nuv = scaf_param_uv_count(p);
    UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    if (!UV || !FT) {
        fprintf(stderr, "scaf param: out of memory\n");
        rc = EXIT_NOMEM;
        goto done;
    }
    if (scaf_param_get_uv(p, UV, FT) != SCAF_OK) {
        fprintf(stderr, "scaf param: %s: %s\n", in, scaf_param_error(p));
        rc = EXIT_NUMERIC;
        goto done;
    }
    /* the figure users compare (docs/energy.md): the optimizer's E is at
     * the layout's scale */
    double e_matched = NAN;
    scaf_area_matched_energy(m.V, m.nv, m.F, m.nf, UV, nuv, FT, &e_matched);
    if (!quiet) {
        fprintf(stderr,
                "scaf param: %d iterations, E %.6f (area-matched; objective %.6f -> %.6f), %.3f "
                "s%s\n",
                scaf_param_iterations(p), e_matched, e0, e1, timer_now() - t_start,
                verify ? " (bijective after every iteration: verified)" : "");
        scaf_stop_reason why = scaf_param_stop_reason(p);
        fprintf(stderr, "scaf param: stop reason: %s (%s), criterion %.3g\n",
                scaf_stop_reason_name(why), stop_reason_explained(why), ps.criterion);
    }
    mesh o = {m.nv, m.V, m.nf, m.F, nuv, UV, FT};
    if ((rc = cli_uv_job_write_map(&job, &o)) != EXIT_OK) goto done;
    cli_gltf_pieces_report("param", in, &job.rinfo, quiet, &o);
    const char *path;
    if (svg) {
        param_map pm;
        param_working_map(p, &pm);
        double *E = malloc(sizeof(double) * (size_t)m.nf);
        uv_svg_scaffold ss = {0};
        if (E) param_face_energy(p, E);
        scaffold_view sv;
        param_last_scaffold(p, &sv);
        if (svg_scaffold && sv.n > 0) {
            ss.ntri = sv.n;
            ss.T = sv.simplices;
            ss.extra = sv.extra;
        }
        char title[256];
        snprintf(title, sizeof title, "%s: E = %.5f after %d iterations (4 = isometry)", in, e1,
                 scaf_param_iterations(p));
        /* Working vertex ids are the UV ids: draw with the loop's faces. */
        path = cli_outputs_begin(&job.outs, job.k.svg, &err);
        st = path
            ? uv_svg_write(path, pm.nuv, pm.uv, pm.nf, pm.FT, E, ss.ntri ? &ss : NULL, title, &err)
            : SCAF_ERR_IO;
        free(E);
        if ((rc = cli_outputs_end(&job.outs, job.k.svg, st, &err)) != EXIT_OK) goto done;
    }
    if (png.path) {
        /* same colours as the SVG; the loop's first nf faces are the mesh's, in order */
        param_map pm;
        param_working_map(p, &pm);
        double *E = malloc(sizeof(double) * (size_t)(pm.nf ? pm.nf : 1));
        if (!E) {
            fprintf(stderr, "scaf param: out of memory\n");
            rc = EXIT_NOMEM;
            goto done;
        }
        param_face_energy(p, E);
        uv_png_options po = png.opt;
        po.energy_legend = !png.plain; /* the colours are the distortion scale's: its bar */
        rc = cli_uv_job_png(&job, pm.nuv, pm.uv, pm.nf, pm.FT, energy_colour, E, m.nv, m.V, m.F,
                            &po);
        free(E);
        if (rc != EXIT_OK) goto done;
    }
    if (job.png_seams >= 0 || report) {
        /* the chart of every face: the pieces of the output's UV topology */
        fc = malloc(sizeof(int) * (size_t)m.nf);
        if (!fc || chart_gap_labels(nuv, m.nf, FT, fc, &nc, &err) != SCAF_OK) {
            fprintf(stderr, "scaf param: %s\n", fc ? err.message : "out of memory");
            rc = fc ? exit_code_for(err.code) : EXIT_NOMEM;
            goto done;
        }
    }
    if (job.png_seams >= 0 &&
        (rc = cli_seams_png(&job.outs, job.png_seams, &m, fc, &seams, NULL)) != EXIT_OK)
        goto done;
    if (report) {
        seam_report sr = {
            scaf_param_seams_used(p), param_seams_why(p), nc, m.nf, fc, &seams, NULL, 0};
        gltf_piece *pieces = NULL; /* a glTF input: which primitive went where */
        cli_gltf_pieces_load("param", in, &job.rinfo, quiet, &pieces, &sr.npieces);
        sr.pieces = pieces;
        param_report r = {in,    out,   &opt, m.nv,      m.nf, scaf_param_chart_count(p),
                          setup, e0,    e1,   e_matched, "ok", scaf_param_stop_reason(p),
                          ps.n,  ps.it, &sr};
        path = cli_outputs_begin(&job.outs, job.k.report, &err);
        st = path ? param_report_write(path, &r, &err) : SCAF_ERR_IO;
        free(pieces);
        if ((rc = cli_outputs_end(&job.outs, job.k.report, st, &err)) != EXIT_OK) goto done;
    }
    rc = cli_outputs_commit(&job.outs);
done:
    cli_outputs_abort(&job.outs);
    seam_edges_free(&seams);
    free(fc);
    free(UV);
    free(FT);
    free(ps.it);
    scaf_param_destroy(p);
    mesh_free(&m);
    return rc;
}

/* SIGINT / SIGTERM: exit 8 at the next safe point (tools/cli_signal) */
int cmd_param(int argc, char **argv) { return cli_signal_run(param_main, argc, argv); }
