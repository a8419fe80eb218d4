/* fuzz/fuzz_cli: libFuzzer target for the `scaf` commands, run in-process.
 *
 * The input becomes a tiny mesh with extreme coordinates and a command
 * line of option names and values, and `scaf param`, `scaf atlas` or
 * `scaf check` runs on it through its entry point (tools/cmd_*.c):
 *   byte 0       command: param, atlas, check (% 3)
 *   byte 1       grid side 2 + b % 3 (a (side+1)^2-vertex grid, 2 side^2
 *                triangles)
 *   byte 2       scale of the positions (table `scales`: 1e-300 .. 1e308,
 *                subnormal)
 *   byte 3       offset of the positions (table `offsets`)
 *   byte 4       flags: bit 0 the file has UVs, bit 1 UVs scaled like the
 *                positions (else the unit grid), bit 2 UV jitter large
 *                enough to fold, bit 3 a second copy of the grid (two charts)
 *   then         per vertex 3 jitter bytes (positions) and 2 (UVs)
 *   then         up to 10 pairs (option, value): option b % number of
 *                option names of the command (table `options`), value an
 *                index into `values` (numbers at and beyond the edges of
 *                every range, garbage, names, and output paths: plain, .gz,
 *                .ply, the input itself, a symbolic link, a FIFO, a
 *                directory, a missing folder).
 * The command line ends with iteration caps (the last value of an option
 * wins), so a run stays short whatever the fuzzer asks for. Missing bytes
 * read as zero.
 *
 * Whatever the input, the command must never crash, hang or leak, must
 * return an exit status from 0 to 7 (not 8: no signal is sent; not 70:
 * "internal error" is a bug in scaf; 1 only from check), leave no
 * temporary file behind, and a mesh written with exit 0 must be bijective
 * by the exact checker. Anything else aborts. FUZZ_CLI_PRINT=1 in the
 * environment prints each command line (to triage an input).
 */
#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/atlas.h"
#include "exit_codes.h"
#include "geom/bijectivity.h"
#include "mesh/mesh_io.h"

int cmd_param(int argc, char **argv);
int cmd_atlas(int argc, char **argv);
int cmd_check(int argc, char **argv);

/* The atlas packer's default 1024-cell raster takes seconds per run under
 * the sanitizers: the target is linked with
 * -Wl,--wrap=atlas_options_default, so `scaf atlas` starts from these
 * defaults with a 64-cell raster (as fuzz_param). */
atlas_options __real_atlas_options_default(void);
atlas_options __wrap_atlas_options_default(void);
atlas_options __wrap_atlas_options_default(void)
{
    atlas_options o = __real_atlas_options_default();
    o.pack_cells = 64;
    return o;
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char dir[256]; /* scratch folder of every run */

static const double scales[] = {1.0,      1e-300, 1e-200, 1e-80, 1e-30, 1e-8,  1e8,   1e30,
                                1e80,     1e154,  1e155,  1e200, 1e300, 1e307, 1e308, 4.9e-324,
                                2.2e-308, 1e-160, 1e160,  -1.0,  0.0,   3.0,   1e15,  1e-15};
static const double offsets[] = {0.0, 1.0, -1e10, 1e15, 1e200, -1e300, 1e-300, 0.5};

/* Option names per command; the values are taken from `values`. */
static const char *const param_names[] = {"-o",
                                          "--output",
                                          "--iterations",
                                          "--tolerance",
                                          "--energy",
                                          "--init",
                                          "--box-scale",
                                          "--lambda-ratio",
                                          "--min-angle",
                                          "--quiet",
                                          "--report",
                                          "--svg",
                                          "--svg-scaffold",
                                          "--png",
                                          "--png-size",
                                          "--checker",
                                          "--verify",
                                          "-h",
                                          "--bogus",
                                          "-q"};
static const char *const atlas_names[] = {"-o",
                                          "--output",
                                          "--padding",
                                          "--resolution",
                                          "--padding-texels",
                                          "--init",
                                          "--iterations",
                                          "--compact-iterations",
                                          "--distortion-tolerance",
                                          "--box-scale",
                                          "--lambda-ratio",
                                          "--compact-lambda-ratio",
                                          "--quiet",
                                          "--report",
                                          "--svg",
                                          "--png",
                                          "--png-size",
                                          "--checker",
                                          "-h",
                                          "--bogus"};
static const char *const check_names[] = {"--json", "-h", "--bogus", "--json"};
/* options that take no value (the fuzzer's value byte is then skipped) */
static const char *const flags[] = {"--quiet", "-q",     "--svg-scaffold", "--verify",
                                    "-h",      "--json", "--bogus"};

/* Values; "@NAME" is the file NAME in the scratch folder, "-" after an
 * option naming a file is the standard output. A valid PNG size above 64
 * pixels is capped at the end of the command line, as the iterations are:
 * a run must stay small (--png-size 10000 took 16 s in zlib). */
static const char *const values[] = {"0",          "1",
                                     "2",          "3",
                                     "-1",         "1e-61",
                                     "1e-300",     "1e300",
                                     "1e308",      "4.9e-324",
                                     "nan",        "inf",
                                     "-inf",       "",
                                     "abc",        "100000000",
                                     "100000001",  "2147483648",
                                     "0.5",        "0.49",
                                     "0.4999999",  "1e-5",
                                     "15",         "16",
                                     "64",         "16385",
                                     "20",         "60",
                                     "89",         "90",
                                     "179",        "1e-320",
                                     "0x10",       "1e",
                                     " 1",         "1 ",
                                     "-0",         "sd",
                                     "arap",       "conformal",
                                     "mips",       "symmetric-dirichlet",
                                     "tutte",      "harmonic",
                                     "mvc",        "input",
                                     "0.01",       "10000",
                                     "10001",      "1024",
                                     "@o.obj",     "@o.obj.gz",
                                     "@o.ply",     "@o.off",
                                     "@o",         "@r.json",
                                     "@r.json.gz", "@s.svg",
                                     "@p.png",     "@in.obj",
                                     "@link.obj",  "@fifo.obj",
                                     "@dir.obj",   "@nodir/x.obj",
                                     "@",          "@-",
                                     "@o.OBJ",     "-"};

/* Options naming a file: their value is always a name in the scratch
 * folder (never the working directory). */
static const char *const path_options[] = {"-o", "--output", "--report", "--svg", "--png"};

/* The scratch folder's fixed entries; everything else is removed after a
 * run. */
static const char *const fixed[] = {"in.obj", "fifo.obj", "dir.obj", "link.obj"};

typedef struct reader {
    const uint8_t *p;
    size_t n, i;
} reader;

static unsigned next_byte(reader *r) { return r->i < r->n ? r->p[r->i++] : 0u; }

static void path_of(char *buf, size_t size, const char *name)
{
    snprintf(buf, size, "%s/%s", dir, name);
}

static void remove_scratch(void);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/scaf_fuzz_cli_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(dir)) abort();
    char p[512];
    path_of(p, sizeof p, "fifo.obj");
    if (mkfifo(p, 0644) != 0) abort();
    path_of(p, sizeof p, "dir.obj");
    if (mkdir(p, 0755) != 0) abort();
    path_of(p, sizeof p, "link.obj");
    if (symlink("o.obj", p) != 0) abort();
    atexit(remove_scratch);
    return 0;
}

/* The grid mesh as an OBJ file; 0 when it cannot be written. */
static int write_mesh(reader *r, const char *path)
{
    int side = 2 + (int)(next_byte(r) % 3);
    double scale = scales[next_byte(r) % (sizeof scales / sizeof scales[0])];
    double offset = offsets[next_byte(r) % (sizeof offsets / sizeof offsets[0])];
    unsigned fl = next_byte(r);
    int uv = fl & 1, uv_scaled = fl & 2, fold = fl & 4, copies = fl & 8 ? 2 : 1;
    int n = side + 1;
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    for (int c = 0; c < copies; c++)
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                double jx = (int)next_byte(r) - 128, jy = (int)next_byte(r) - 128,
                       jz = (int)next_byte(r) - 128;
                double x = (j + 3.0 * c + jx / 1024.0) * scale + offset,
                       y = (i + jy / 1024.0) * scale + offset;
                fprintf(f, "v %.17g %.17g %.17g\n", x, y, jz / 256.0 * scale);
                if (uv) {
                    double k = fold ? 1.0 / 128.0 : 1.0 / 1024.0;
                    double u = (j + 3.0 * c + ((int)next_byte(r) - 128) * k) / (3.0 * copies);
                    double v = (i + ((int)next_byte(r) - 128) * k) / 3.0;
                    if (uv_scaled) u = u * scale + offset, v = v * scale + offset;
                    fprintf(f, "vt %.17g %.17g\n", u, v);
                }
            }
    for (int c = 0; c < copies; c++)
        for (int i = 0; i < side; i++)
            for (int j = 0; j < side; j++) {
                int a = c * n * n + i * n + j + 1, b = a + 1, d = a + n, e = d + 1;
                if (uv)
                    fprintf(f, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a, b, b, e, e, a, a,
                            e, e, d, d);
                else fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, e, a, e, d);
            }
    return fclose(f) == 0;
}

static int listed(const char *s, const char *const *list, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!strcmp(s, list[i])) return 1;
    return 0;
}

/* Remove what the last run wrote (a regular file: never the FIFO, the
 * folder or the link). */
static void clean_scratch(void)
{
    DIR *d = opendir(dir);
    if (!d) abort();
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") ||
            listed(e->d_name, fixed, sizeof fixed / sizeof fixed[0]))
            continue;
        char p[512];
        path_of(p, sizeof p, e->d_name);
        struct stat st;
        if (lstat(p, &st) == 0 && S_ISREG(st.st_mode)) remove(p);
    }
    closedir(d);
}

/* No hidden (temporary) file may be left in the scratch folder. */
static void assert_no_temporary(void)
{
    DIR *d = opendir(dir);
    if (!d) abort();
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            fprintf(stderr, "fuzz_cli: temporary file left: %s/%s\n", dir, e->d_name);
            abort();
        }
    closedir(d);
}

/* Remove the scratch folder when the fuzzer exits. */
static void remove_scratch(void)
{
    clean_scratch();
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
        char p[512];
        path_of(p, sizeof p, fixed[i]);
        if (remove(p) != 0) rmdir(p);
    }
    rmdir(dir);
}

/* The mesh written by a successful param / atlas (-o p) is bijective. */
static void assert_output_bijective(const char *p)
{
    mesh m;
    scaf_error err;
    if (!strcmp(p, "-")) return;
    if (mesh_read(p, &m, NULL, &err) != SCAF_OK) {
        fprintf(stderr, "fuzz_cli: exit 0 but %s unreadable: %s\n", p, err.message);
        abort();
    }
    bij_report rep;
    if (!mesh_has_uv(&m) || bij_check(m.nuv, m.UV, m.nf, m.FT, NULL, NULL, &rep, &err) != SCAF_OK ||
        !rep.bijective) {
        fprintf(stderr, "fuzz_cli: %s written but not bijective\n", p);
        abort();
    }
    mesh_free(&m);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    reader r = {data, size, 0};
    unsigned cmd = next_byte(&r) % 3;
    char in[512];
    path_of(in, sizeof in, "in.obj");
    if (!write_mesh(&r, in)) return 0;
    clean_scratch();

    const char *const *opts = cmd == 0 ? param_names : cmd == 1 ? atlas_names : check_names;
    size_t nopts = cmd == 0 ? sizeof param_names / sizeof param_names[0]
        : cmd == 1          ? sizeof atlas_names / sizeof atlas_names[0]
                            : sizeof check_names / sizeof check_names[0];
    enum { MAX_ARGS = 40, ARG_LEN = 320 };
    static char store[MAX_ARGS][ARG_LEN];
    char *argv[MAX_ARGS + 1];
    int argc = 0, mesh_out = -1, help = 0;
#define PUSH(s) (snprintf(store[argc], ARG_LEN, "%s", (s)), argv[argc] = store[argc], argc++)
    PUSH(cmd == 0 ? "param" : cmd == 1 ? "atlas" : "check");
    PUSH(in);
    int big_png = 0; /* a --png-size above 64 pixels */
    for (int k = 0; k < 10 && r.i < r.n; k++) {
        const char *o = opts[next_byte(&r) % nopts];
        unsigned vb = next_byte(&r);
        PUSH(o);
        if (!strcmp(o, "-o") || !strcmp(o, "--output")) mesh_out = argc; /* its value comes next */
        if (!strcmp(o, "-h")) help = 1; /* exit 0, nothing written */
        if (listed(o, flags, sizeof flags / sizeof flags[0]) && vb < 240)
            continue; /* sometimes a stray value after a flag */
        const char *v = values[vb % (sizeof values / sizeof values[0])];
        if (!strcmp(o, "--png-size") && atof(v) > 64) big_png = 1;
        int is_path = listed(o, path_options, sizeof path_options / sizeof path_options[0]);
        if (is_path && !strcmp(v, "-")) {
            PUSH(v); /* standard output */
        } else if (v[0] == '@' || is_path) {
            char p[512];
            path_of(p, sizeof p, v[0] == '@' ? v + 1 : v);
            PUSH(p);
        } else {
            PUSH(v);
        }
    }
    /* caps last: the last value of an option wins (a value the command
     * refuses stops it before) */
    if (big_png) {
        PUSH("--png-size");
        PUSH("64");
    }
    if (cmd == 0) {
        PUSH("--iterations");
        PUSH("3");
    } else if (cmd == 1) {
        PUSH("--iterations");
        PUSH("2");
        PUSH("--compact-iterations");
        PUSH("2");
    }
#undef PUSH
    argv[argc] = NULL;

    if (getenv("FUZZ_CLI_PRINT")) { /* triage: show the command line of an input */
        fprintf(stderr, "fuzz_cli: scaf");
        for (int i = 0; i < argc; i++) fprintf(stderr, " '%s'", argv[i]);
        fputc('\n', stderr);
    }
    int rc = cmd == 0 ? cmd_param(argc, argv)
        : cmd == 1    ? cmd_atlas(argc, argv)
                      : cmd_check(argc, argv);
    /* 0..7; not 8 (no signal), not 70 (a bug in scaf, by definition) */
    int expected = rc >= EXIT_OK && rc <= EXIT_NOMEM && (rc != EXIT_NOT_BIJECTIVE || cmd == 2);
    if (!expected) {
        fprintf(stderr, "fuzz_cli: exit status %d:", rc);
        for (int i = 0; i < argc; i++) fprintf(stderr, " '%s'", argv[i]);
        fputc('\n', stderr);
        abort();
    }
    assert_no_temporary();
    if (rc == EXIT_OK && cmd != 2 && !help && mesh_out >= 0 && mesh_out < argc)
        assert_output_bijective(argv[mesh_out]);
    return 0;
}
