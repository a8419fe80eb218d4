/* tools/main: the `scaf` program: dispatches to one subcommand. */
#include <stdio.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"
#include "cli_options.h"
#include "commands.h"
#include "exit_codes.h"
#include "scaf/scaf.h"

/* Add a subcommand: write tools/cmd_NAME.c with `int cmd_NAME(int, char **)`,
 * declare it here and list it in the table. */
int cmd_check(int argc, char **argv);
int cmd_gen(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_param(int argc, char **argv);
int cmd_atlas(int argc, char **argv);
int cmd_tet(int argc, char **argv);
int cmd_deform(int argc, char **argv);
int cmd_flow(int argc, char **argv);
int cmd_edit(int argc, char **argv);
int cmd_untangle(int argc, char **argv);
int cmd_inflate(int argc, char **argv);

const command scaf_commands[] = {
    {"check",
     "verify a UV map is bijective, a surface free of self-intersections, tets positive (exact)",
     cmd_check},
    {"gen", "write a built-in sample mesh (hemisphere, holes, cubesphere, ...)", cmd_gen},
    {"info", "print the topology of a mesh (components, loops, genus, defects, charts)", cmd_info},
    {"param", "bijective UV parametrization with SCAF (writes OBJ with vt)", cmd_param},
    {"atlas", "multi-chart texture atlas: joint bijective optimization, compaction, padding",
     cmd_atlas},
    {"deform", "deform a planar mesh towards handle targets, bijectively (soft constraints)",
     cmd_deform},
    {"edit", "interactive atlas editor in the browser: drag charts, nothing overlaps", cmd_edit},
    {"flow",
     "conformalized mean curvature flow of a closed surface (until free of self-intersections)",
     cmd_flow},
    {"untangle",
     "remove the self-intersections of a closed genus-0 surface (flow out, SCAF loop back)",
     cmd_untangle},
    {"inflate",
     "grow a closed surface toward K times its size in a box, never self-intersecting (3D SCAF)",
     cmd_inflate},
    {"tet", "tetrahedralize a box around a closed surface (TetGen, surface kept, checked exactly)",
     cmd_tet},
    {NULL, NULL, NULL}};

/* The solver frees and reallocates its factor (hundreds of MB on big
 * meshes) every iteration. glibc serves such blocks with fresh mmap pages,
 * so each iteration page-faulted its whole factor anew (aphrodite.obj:
 * ~17k faults, a fifth of the process time in the kernel). Keep big
 * blocks in the heap and never trim it (-1): freed memory is reused as is;
 * the peak is unchanged. */
static void tune_allocator(void)
{
#ifdef __GLIBC__
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1); /* never give the heap back */
#endif
}

/* One BLAS thread unless OPENBLAS_NUM_THREADS says otherwise (`scaf param`
 * and `scaf atlas` then choose with --threads, tools/cli_threads): results
 * are then the same on every machine (threaded BLAS sums in another order),
 * and on a busy machine two spinning BLAS threads made the factorization
 * several times slower (bench/RESULTS-param.md). */
static void default_threads(void)
{
    const char *e = getenv("OPENBLAS_NUM_THREADS");
    if (!e || !*e) scaf_set_threads(1);
}

/* SCAF_MIN_CHUNK=N: scaf's loops are cut into chunks of at least N items
 * (default PAR_MIN_CHUNK, 4096) so that tests take the parallel paths on
 * small inputs (docs/param.md). Not a number >= 1: ignored. */
static void min_chunk_from_environment(void)
{
    const char *e = getenv("SCAF_MIN_CHUNK");
    if (!e || !*e) return;
    char *end;
    long n = strtol(e, &end, 10);
    if (*end == '\0' && n >= 1) par_set_min_chunk((size_t)n);
}

static void help_about(FILE *out)
{
    fputs("Bijective maps with the Simplicial Complex Augmentation Framework.\n\ncommands:\n", out);
    for (const command *c = scaf_commands; c->name; c++)
        fprintf(out, "  %-8s %s\n", c->name, c->summary);
    fputc('\n', out);
}

static void help_after(FILE *out)
{
    fprintf(out,
            "\n"
            "`scaf COMMAND --help` describes a command. Every command takes --name=VALUE\n"
            "or --name VALUE, grouped short options (-qo OUT), and -- to end the options\n"
            "(docs/cli.md). `scaf param` and `scaf atlas` run their per-triangle work and\n"
            "the sparse solver's dense kernels on all cores unless --threads N or\n"
            "OPENBLAS_NUM_THREADS=N says N (the same N gives the same numbers run after\n"
            "run); the other commands use one thread.\n"
            "\n");
    exit_codes_print(out);
}

static int version;

/* The options before the command: --help, --version. */
static const cli_option global_table[] = {
    CLI_GROUP("options:"),
    CLI_FLAG("version", 0, &version, "print the version of scaf"),
    CLI_OPTION_HELP,
    {0}};

static const cli_command_options global = {.cmd = "", /* messages read "scaf: ..." */
                                           .usage = "usage: scaf COMMAND [options] ...\n"
                                                    "       scaf --help | --version\n\n",
                                           .about = help_about,
                                           .after = help_after,
                                           .options = global_table,
                                           .help_column = 14};

static void print_help(FILE *out) { cli_options_help(&global, out); }

static int global_options(int argc, char **argv)
{
    int rc = cli_options_parse(&global, argc, argv);
    if (rc != CLI_OPTIONS_OK) return cli_options_done(&global, rc);
    if (version) printf("scaf %s\n", scaf_version());
    return EXIT_OK;
}

int main(int argc, char **argv)
{
    tune_allocator();
    default_threads();
    min_chunk_from_environment();
    if (argc < 2) {
        print_help(stderr);
        return EXIT_USAGE;
    }
    if (!strcmp(argv[1], "help")) {
        print_help(stdout);
        return EXIT_OK;
    }
    if (argv[1][0] == '-' && argv[1][1]) return global_options(argc, argv);
    for (const command *c = scaf_commands; c->name; c++)
        if (!strcmp(argv[1], c->name)) return c->run(argc - 1, argv + 1);
    fprintf(stderr, "scaf: unknown command '%s' (see `scaf --help`)\n", argv[1]);
    return EXIT_USAGE;
}
