/* tools/cli_outputs: the set of files one run writes, committed together.
 *
 * A command declares its outputs (-o, --report, --svg, --png ...) and its
 * input, and cli_outputs_check refuses, before any work:
 *   - a mesh output whose extension scaf cannot write (exit 2): OBJ
 *     (.obj) and PLY (.ply, binary with per-corner `texcoord` lists),
 *     each optionally .gz (written gzip-compressed), carry the per-corner
 *     texture coordinates; .off, .stl and unknown names are refused;
 *   - an output that is a directory, FIFO, device or socket, or whose
 *     folder is missing or not writable (exit 5; a temporary file is
 *     created and removed there to prove it);
 *   - two of the input and the outputs naming the same file, after
 *     symbolic links (same device and inode, or the same canonical path for
 *     files not there yet) (exit 2).
 * A symbolic link as output is written through: the file it points to is
 * replaced (base/atomic_file), the link stays. Any name ending in .gz is
 * written gzip-compressed. "-" is the standard output (written last, once
 * the files are committed; a mesh there is a plain OBJ).
 *
 * Writing: for each output, cli_outputs_begin gives the path the writer
 * writes to (a hidden temporary file beside the target, which the path
 * writers of src/ replace atomically in their turn), cli_outputs_end takes
 * the writer's status (its message, which names that temporary path, is
 * printed with the output's own name) and gzips when asked.
 * cli_outputs_commit then renames every temporary file over its target,
 * or, when one write failed or SIGINT / SIGTERM arrived (tools/cli_signal),
 * removes them all and leaves every existing file as it was: all outputs
 * are committed or none is. The renames start only once every file is
 * complete and synced; one can still fail if the folder changes under the
 * run (reported, exit 5).
 */
#ifndef SCAF_TOOLS_CLI_OUTPUTS_H
#define SCAF_TOOLS_CLI_OUTPUTS_H

#include "base/atomic_file.h"
#include "base/error.h"

#define CLI_OUTPUTS_MAX 8

/* The paragraph of the commands' --help that says the above. */
#define CLI_OUTPUTS_HELP                                                                           \
    "\n"                                                                                           \
    "Output files: -o ends in .obj (the input OBJ again with new vt, or a plain OBJ)\n"            \
    "or .ply (binary little-endian PLY, double x y z and a texcoord list per face);\n"             \
    "any output ending in .gz is compressed. Every output is checked before the work starts\n"     \
    "and all are written together at the end, or none is: a directory, FIFO or\n"                  \
    "device, a missing or read-only folder, or two of the input and the outputs\n"                 \
    "naming the same file are refused. A symbolic link is written through (the\n"                  \
    "file it points to is replaced). \"-\" writes to the standard output.\n"

typedef enum cli_output_kind {
    CLI_OUTPUT_MESH,    /* a mesh: .obj or .obj.gz */
    CLI_OUTPUT_UV_MESH, /* the mesh with its UVs (param, atlas, deform): .obj or .ply,
                           optionally .gz */
    CLI_OUTPUT_FILE     /* a report or picture: any name */
} cli_output_kind;

typedef struct cli_output {
    const char *option; /* "-o", "--report", ... for messages */
    const char *path;   /* as given */
    cli_output_kind kind;
    int gz;             /* name ends in .gz: compress */
    atomic_file staged; /* the temporary file holding the result */
    int written;        /* staged holds the whole result */
    int to_stdout;      /* the path is "-" */
} cli_output;

#define CLI_INPUTS_MAX 4

typedef struct cli_outputs {
    const char *cmd; /* "param", ... for messages */
    int ninputs;
    const char *input[CLI_INPUTS_MAX];        /* files the run reads: never overwritten */
    const char *input_option[CLI_INPUTS_MAX]; /* "the input", "--targets", ... */
    int n;
    cli_output out[CLI_OUTPUTS_MAX];
    char message[512]; /* the last refusal cli_outputs_check printed, without
                          "scaf CMD: " ("" when none): `scaf edit` sends
                          it to the page */
} cli_outputs;

void cli_outputs_init(cli_outputs *o, const char *cmd, const char *input);

/* Another file the run reads (e.g. `--targets`): no output may name it.
 * NULL is ignored. */
void cli_outputs_add_input(cli_outputs *o, const char *option, const char *path);

/* Declare an output; returns its index, or -1 when path is NULL (not
 * asked for: begin/end then do nothing). */
int cli_outputs_add(cli_outputs *o, const char *option, const char *path, cli_output_kind kind);

/* The checks above: 0, or the exit status after printing why. */
int cli_outputs_check(cli_outputs *o);

/* The outputs of `scaf param` and `scaf atlas`: their indices (-1: not
 * asked for). */
typedef struct cli_uv_outputs {
    int mesh, svg, png, report;
} cli_uv_outputs;

/* Declare -o (the mesh), --svg, --png and --report (each may be NULL)
 * and check them all: 0, or the exit status after printing why. */
int cli_outputs_uv(cli_outputs *o, const char *mesh, const char *svg, const char *png,
                   const char *report, cli_uv_outputs *k);

/* The path output k's writer writes to (NULL after printing why; pass
 * its failure on to cli_outputs_end). */
const char *cli_outputs_begin(cli_outputs *o, int k, scaf_error *err);

/* The writer of output k returned st (err its message, naming the path
 * begin gave: it is reported under the output's own name): 0, or the exit
 * status after printing why (5, 7 out of memory). k < 0: 0. */
int cli_outputs_end(cli_outputs *o, int k, scaf_status st, scaf_error *err);

/* Rename every written output over its target: 0, or the exit status
 * after printing why (5; 8 when interrupted) with nothing committed. */
int cli_outputs_commit(cli_outputs *o);

/* Remove every temporary file (after commit: nothing left to do). */
void cli_outputs_abort(cli_outputs *o);

#endif
