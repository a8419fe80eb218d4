/* tools/cli_outputs: see cli_outputs.h. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "cli_outputs.h"

#include <ctype.h>
#include <stdarg.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "cli_signal.h"
#include "exit_codes.h"

/* Print "scaf CMD: message" and keep the message for the caller. */
static void say(cli_outputs *o, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void say(cli_outputs *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(o->message, sizeof o->message, fmt, ap);
    va_end(ap);
    fprintf(stderr, "scaf %s: %s\n", o->cmd, o->message);
}

void cli_outputs_init(cli_outputs *o, const char *cmd, const char *input)
{
    memset(o, 0, sizeof *o);
    o->cmd = cmd;
    cli_outputs_add_input(o, "the input", input);
}

void cli_outputs_add_input(cli_outputs *o, const char *option, const char *path)
{
    if (!path || o->ninputs >= CLI_INPUTS_MAX) return;
    o->input_option[o->ninputs] = option;
    o->input[o->ninputs++] = path;
}

int cli_outputs_add(cli_outputs *o, const char *option, const char *path, cli_output_kind kind)
{
    if (!path || o->n == CLI_OUTPUTS_MAX) return -1;
    cli_output *c = &o->out[o->n];
    memset(c, 0, sizeof *c);
    c->option = option;
    c->path = path;
    c->kind = kind;
    return o->n++;
}

/* Whether path ends in suffix, ignoring case. */
static int ends_with(const char *path, const char *suffix)
{
    size_t n = strlen(path), k = strlen(suffix);
    if (n < k) return 0;
    for (size_t i = 0; i < k; i++)
        if (tolower((unsigned char)path[n - k + i]) != suffix[i]) return 0;
    return 1;
}

static int check_format(cli_outputs *o, cli_output *c)
{
    c->gz = ends_with(c->path, ".gz");
    int uv = c->kind == CLI_OUTPUT_UV_MESH; /* PLY too */
    if (c->kind == CLI_OUTPUT_FILE || c->to_stdout || ends_with(c->path, ".obj") ||
        ends_with(c->path, ".obj.gz") ||
        (uv && (ends_with(c->path, ".ply") || ends_with(c->path, ".ply.gz"))))
        return 0;
    const char *names = uv ? ".obj or .ply (optionally .gz)" : ".obj or .obj.gz";
    static const char *const no_uv[][2] = {{".ply", "PLY"},    {".off", "OFF"},
                                           {".stl", "STL"},    {".ply.gz", "PLY"},
                                           {".off.gz", "OFF"}, {".stl.gz", "STL"}};
    for (size_t i = 0; i < sizeof no_uv / sizeof no_uv[0]; i++)
        if (ends_with(c->path, no_uv[i][0])) {
            if (uv)
                say(o,
                    "%s %s: scaf cannot write %s (it has no per-corner texture coordinates); "
                    "name the output %s",
                    c->option, c->path, no_uv[i][1], names);
            else
                say(o, "%s %s: scaf %s writes OBJ only; name the output %s", c->option, c->path,
                    o->cmd, names);
            return EXIT_USAGE;
        }
    say(o, "%s %s: unknown output format; name the output %s (.gz: gzip-compressed)", c->option,
        c->path, names);
    return EXIT_USAGE;
}

/* Where a file is: its device and inode when it exists, else its
 * canonical path (links followed). */
typedef struct file_id {
    char path[4096];
    int exists;
    dev_t dev;
    ino_t ino;
} file_id;

static int same_file(const file_id *a, const file_id *b)
{
    if (a->exists && b->exists) return a->dev == b->dev && a->ino == b->ino;
    return !strcmp(a->path, b->path);
}

static void id_stat(file_id *id)
{
    struct stat st;
    id->exists = stat(id->path, &st) == 0;
    if (id->exists) {
        id->dev = st.st_dev;
        id->ino = st.st_ino;
    }
}

int cli_outputs_check(cli_outputs *o)
{
    /* ids[k]: output k; in[i]: input i (when it exists) */
    file_id *ids = calloc((size_t)o->n + 1, sizeof *ids);
    file_id in[CLI_INPUTS_MAX];
    int have[CLI_INPUTS_MAX] = {0};
    if (!ids) {
        say(o, "out of memory");
        return EXIT_NOMEM;
    }
    int rc = EXIT_OK;
    scaf_error err;
    err_clear(&err);
    for (int i = 0; i < o->ninputs; i++) {
        memset(&in[i], 0, sizeof in[i]);
        char *real = realpath(o->input[i], NULL);
        if (real && strlen(real) < sizeof in[i].path) {
            strcpy(in[i].path, real);
            id_stat(&in[i]);
            have[i] = 1;
        }
        free(real);
    }
    for (int k = 0; k < o->n && !rc; k++) {
        o->out[k].to_stdout = !strcmp(o->out[k].path, "-");
        if (!o->out[k].path[0]) { /* -o "": a bad command line, not a failed write */
            fprintf(stderr, "scaf %s: %s: the file name is empty\n", o->cmd, o->out[k].option);
            rc = EXIT_USAGE;
        } else if (o->out[k].to_stdout) {
            strcpy(ids[k].path, "-"); /* not a path: only another "-" is the same */
            rc = check_format(o, &o->out[k]);
        } else if (atomic_resolve(o->out[k].path, ids[k].path, sizeof ids[k].path, NULL, &err) !=
                   SCAF_OK) {
            say(o, "%s %s", o->out[k].option, err.message);
            rc = EXIT_OUTPUT;
        } else {
            id_stat(&ids[k]);
            rc = check_format(o, &o->out[k]);
        }
    }
    for (int k = 0; k < o->n && !rc; k++) {
        for (int i = 0; i < o->ninputs && !rc; i++)
            if (have[i] && same_file(&in[i], &ids[k])) {
                say(o, "%s and %s name the same file (%s): it would be overwritten",
                    o->input_option[i], o->out[k].option, o->out[k].path);
                rc = EXIT_USAGE;
            }
        for (int j = 0; j < k && !rc; j++)
            if (same_file(&ids[j], &ids[k])) {
                say(o, "%s and %s name the same file (%s): give each output its own file",
                    o->out[j].option, o->out[k].option, o->out[k].path);
                rc = EXIT_USAGE;
            }
    }
    free(ids);
    /* writable: create and remove the temporary file the write will use */
    for (int k = 0; k < o->n && !rc; k++) {
        if (o->out[k].to_stdout) continue;
        atomic_file probe;
        if (atomic_open(&probe, o->out[k].path, &err) != SCAF_OK) {
            say(o, "%s %s", o->out[k].option, err.message);
            rc = EXIT_OUTPUT;
        }
        atomic_abort(&probe);
    }
    return rc;
}

int cli_outputs_uv(cli_outputs *o, const char *mesh, const char *svg, const char *png,
                   const char *report, cli_uv_outputs *k)
{
    k->mesh = cli_outputs_add(o, "-o", mesh, CLI_OUTPUT_UV_MESH);
    k->svg = cli_outputs_add(o, "--svg", svg, CLI_OUTPUT_FILE);
    k->png = cli_outputs_add(o, "--png", png, CLI_OUTPUT_FILE);
    k->report = cli_outputs_add(o, "--report", report, CLI_OUTPUT_FILE);
    return cli_outputs_check(o);
}

/* Standard output: the writer writes a temporary file in $TMPDIR, copied
 * to stdout when the outputs are committed. */
static const char *stage_for_stdout(cli_output *c, scaf_error *err)
{
    const char *tmp = getenv("TMPDIR");
    atomic_file *a = &c->staged;
    memset(a, 0, sizeof *a);
    a->name = c->path;
    snprintf(a->tmp, sizeof a->tmp, "%s/scaf-stdout-XXXXXX", tmp && *tmp ? tmp : "/tmp");
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        a->tmp[0] = '\0';
        err_set(err, SCAF_ERR_IO, "standard output: cannot create a temporary file in %s",
                tmp && *tmp ? tmp : "/tmp");
        return NULL;
    }
    close(fd);
    a->finished = 1;
    return a->tmp;
}

/* Copy a staged file to stdout; the file is removed first (a reader that
 * closes the pipe early ends the program by SIGPIPE, as usual for a
 * filter, and nothing is left behind). */
static scaf_status copy_to_stdout(atomic_file *staged, scaf_error *err)
{
    FILE *in = fopen(staged->tmp, "rb");
    if (!in)
        return err_set(err, SCAF_ERR_IO, "standard output: cannot read the temporary file back");
    remove(staged->tmp);
    staged->tmp[0] = '\0';
    char buf[1 << 16];
    size_t n;
    int bad = 0;
    while (!bad && (n = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, n, stdout) != n) bad = 1;
    if (ferror(in)) bad = 1;
    fclose(in);
    if (fflush(stdout) != 0) bad = 1;
    return bad ? err_set(err, SCAF_ERR_IO, "standard output: write failed") : SCAF_OK;
}

const char *cli_outputs_begin(cli_outputs *o, int k, scaf_error *err)
{
    if (k < 0) return NULL;
    cli_output *c = &o->out[k];
    atomic_abort(&c->staged);
    c->written = 0;
    if (c->to_stdout) return stage_for_stdout(c, err);
    /* an empty temporary file beside the target: the writer replaces it */
    if (atomic_open(&c->staged, c->path, err) != SCAF_OK ||
        atomic_finish(&c->staged, err) != SCAF_OK) {
        atomic_abort(&c->staged);
        return NULL;
    }
    return c->staged.tmp;
}

/* Replace every occurrence of `from` in err's message by `to`. */
static void rename_in_message(scaf_error *err, const char *from, const char *to)
{
    char out[sizeof err->message];
    size_t n = 0, lf = strlen(from), lt = strlen(to);
    const char *p = err->message, *q;
    if (!lf) return;
    while ((q = strstr(p, from)) != NULL && n + (size_t)(q - p) + lt < sizeof out) {
        memcpy(out + n, p, (size_t)(q - p));
        n += (size_t)(q - p);
        memcpy(out + n, to, lt);
        n += lt;
        p = q + lf;
    }
    snprintf(out + n, sizeof out - n, "%s", p);
    memcpy(err->message, out, sizeof out);
}

/* gzip the finished file src into dst (an open atomic file, finished
 * here). */
static scaf_status gzip_into(const char *src, atomic_file *dst, scaf_error *err)
{
    FILE *in = fopen(src, "rb");
    if (!in)
        return err_set(err, SCAF_ERR_IO, "%s: cannot read the uncompressed file back", dst->name);
    int fd = dup(fileno(dst->f));
    gzFile z = fd >= 0 ? gzdopen(fd, "wb6") : NULL;
    int bad = !z;
    if (!z && fd >= 0) close(fd);
    char buf[1 << 16];
    size_t n;
    while (!bad && (n = fread(buf, 1, sizeof buf, in)) > 0)
        if (gzwrite(z, buf, (unsigned)n) != (int)n) bad = 1;
    if (ferror(in)) bad = 1;
    fclose(in);
    if (z && gzclose(z) != Z_OK) bad = 1;
    scaf_status st = atomic_finish(dst, err); /* syncs what gzclose wrote through the shared file */
    if (bad && st == SCAF_OK)
        st = err_set(err, SCAF_ERR_IO, "%s: gzip compression failed (disk full?)", dst->name);
    return st;
}

int cli_outputs_end(cli_outputs *o, int k, scaf_status st, scaf_error *err)
{
    if (k < 0) return EXIT_OK;
    cli_output *c = &o->out[k];
    if (st == SCAF_OK && !c->staged.tmp[0])
        st = SCAF_ERR_IO; /* begin failed: its message is in err */
    if (st == SCAF_OK && c->gz) {
        atomic_file z;
        st = atomic_open(&z, c->path, err);
        if (st == SCAF_OK) st = gzip_into(c->staged.tmp, &z, err);
        if (st == SCAF_OK) {
            atomic_abort(&c->staged); /* the uncompressed one */
            c->staged = z;
        } else {
            atomic_abort(&z);
        }
    }
    if (st != SCAF_OK) {
        if (c->staged.tmp[0]) rename_in_message(err, c->staged.tmp, c->path);
        fprintf(stderr, "scaf %s: %s; nothing written\n", o->cmd, err->message);
        cli_outputs_abort(o);
        return st == SCAF_ERR_NOMEM ? EXIT_NOMEM : EXIT_OUTPUT;
    }
    c->written = 1;
    cli_signal_test_point(0);
    return EXIT_OK;
}

int cli_outputs_commit(cli_outputs *o)
{
    if (cli_signal_report(o->cmd)) {
        cli_outputs_abort(o);
        return EXIT_CANCELLED;
    }
    for (int k = 0; k < o->n; k++)
        if (!o->out[k].written) {
            fprintf(stderr, "scaf %s: internal error: %s %s was not written; nothing written\n",
                    o->cmd, o->out[k].option, o->out[k].path);
            cli_outputs_abort(o);
            return EXIT_INTERNAL;
        }
    /* every file is complete and synced: only renames are left, then what
     * goes to standard output */
    scaf_error err;
    err_clear(&err);
    for (int k = 0; k < o->n; k++) {
        if (o->out[k].to_stdout) continue;
        if (atomic_rename(&o->out[k].staged, &err) != SCAF_OK) {
            fprintf(stderr, "scaf %s: %s\n", o->cmd, err.message);
            cli_outputs_abort(o);
            return EXIT_OUTPUT;
        }
        o->out[k].written = 0;
    }
    int rc = EXIT_OK;
    for (int k = 0; k < o->n; k++)
        if (o->out[k].to_stdout && rc == EXIT_OK &&
            copy_to_stdout(&o->out[k].staged, &err) != SCAF_OK) {
            fprintf(stderr, "scaf %s: %s\n", o->cmd, err.message);
            rc = EXIT_OUTPUT;
        }
    cli_outputs_abort(o); /* the standard output's temporary files */
    return rc;
}

void cli_outputs_abort(cli_outputs *o)
{
    for (int k = 0; k < o->n; k++) {
        atomic_abort(&o->out[k].staged);
        o->out[k].written = 0;
    }
}
