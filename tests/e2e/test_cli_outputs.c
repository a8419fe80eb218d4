/* End-to-end tests of the output files of `scaf param`, `scaf atlas` and
 * `scaf gen` (tools/cli_outputs, base/atomic_file, tools/cli_signal).
 *
 * Each test works in its own fresh folder, so "no temporary file left"
 * is checked by listing it. What is asserted, per observed bug:
 *   - a symbolic link as output is written through (link kept, target
 *     replaced), also a dangling one;
 *   - a FIFO, a device (/dev/full) or a directory as output: exit 5 before
 *     any work (no progress line), the node unchanged;
 *   - the input, -o, --report, --svg, --png naming one file (directly or
 *     through a link): exit 2, the input unchanged, nothing written;
 *   - a missing or unwritable output folder (for -o, --report, --svg):
 *     exit 5 before any work, no output at all;
 *   - .ply / unknown mesh extensions: exit 2; .obj.gz: gzip, readable;
 *   - "-" is the standard output (never a file named "-"), at most once;
 *     an empty name is a usage error (exit 2, it was 5);
 *   - a write failing in the middle (file size limit: the OBJ fits, the
 *     SVG does not): exit 5, the existing OBJ unchanged, no temporary file;
 *   - SIGINT / SIGTERM / SIGHUP raised by the test hook in the progress
 *     callback or while writing, also twice or several in a row: exit 8,
 *     one line naming the first, existing files unchanged, no temporary
 *     file;
 *   - the file-size limit (ulimit -f) without ignoring SIGXFSZ first: the
 *     write fails, exit 5, no temporary file (it used to be killed by
 *     SIGXFSZ, exit 153, two temporary files left).
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

#include "support/support.h"

/* A fresh folder in the build's scratch folder, and a sample mesh in it. */
static void make_dir(char *dir, size_t size, const char *tag)
{
    char base[256];
    test_tmp_path("", base, sizeof base);
    int n = snprintf(dir, size, "%scli_outputs_%s_XXXXXX", base, tag);
    assert_true(n > 0 && (size_t)n < size);
    assert_non_null(mkdtemp(dir));
    assert_int_equal(test_run("%s gen hemisphere --size 3 -o %s/in.obj", SCAF_BINARY, dir), 0);
}

static void remove_dir(const char *dir) { test_run("rm -rf '%s'", dir); }

/* Hidden files (the temporary files are ".NAME.tmpXXXXXX") in dir. */
static int hidden_files(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            fprintf(stderr, "left behind: %s/%s\n", dir, e->d_name);
            n++;
        }
    closedir(d);
    return n;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static void assert_file_is(const char *path, const char *text)
{
    char *s = test_slurp(path);
    assert_non_null(s);
    assert_string_equal(s, text);
    free(s);
}

/* Run `scaf ARGS` in dir with stderr captured in dir/err.txt (not hidden,
 * so it does not count as a temporary file); returns the exit status. */
static int run_in(const char *dir, const char *env, const char *args)
{
    return test_run("cd '%s' && %s %s %s 2> err.txt", dir, env ? env : "", SCAF_BINARY, args);
}

static char *stderr_of(const char *dir)
{
    char p[600];
    snprintf(p, sizeof p, "%s/err.txt", dir);
    char *s = test_slurp(p);
    assert_non_null(s);
    return s;
}

/* No work started: the run did not get as far as its first progress line. */
static void assert_no_work(const char *dir)
{
    char *e = stderr_of(dir);
    assert_null(strstr(e, "initial E"));
    assert_null(strstr(e, "chart(s)"));
    free(e);
}

static void symlink_output_is_written_through(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "link");
    snprintf(p, sizeof p, "%s/target.obj", dir);
    write_text(p, "old\n");
    assert_int_equal(test_run("cd '%s' && ln -s target.obj link.obj && mkdir sub && ln -s "
                              "../new.obj sub/dangling.obj",
                              dir),
                     0);
    assert_int_equal(run_in(dir, NULL, "param in.obj -o link.obj -q --iterations 2"), 0);
    struct stat st;
    snprintf(p, sizeof p, "%s/link.obj", dir);
    assert_int_equal(lstat(p, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    snprintf(p, sizeof p, "%s/target.obj", dir);
    char *s = test_slurp(p);
    assert_non_null(s);
    assert_non_null(strstr(s, "\nvt "));
    free(s);
    assert_int_equal(test_run("cd '%s' && %s check target.obj > /dev/null", dir, SCAF_BINARY), 0);
    /* a dangling link: the file it names is created, the link stays */
    assert_int_equal(run_in(dir, NULL, "gen hemisphere --size 2 -o sub/dangling.obj"), 0);
    snprintf(p, sizeof p, "%s/sub/dangling.obj", dir);
    assert_int_equal(lstat(p, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    snprintf(p, sizeof p, "%s/new.obj", dir);
    assert_true(test_exists(p));
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void fifo_device_and_directory_are_refused(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "node");
    assert_int_equal(test_run("cd '%s' && mkfifo fifo.obj && mkdir folder.obj", dir), 0);
    struct stat st;

    assert_int_equal(run_in(dir, NULL, "param in.obj -o fifo.obj"), 5);
    assert_no_work(dir);
    char *e = stderr_of(dir);
    assert_non_null(strstr(e, "FIFO"));
    free(e);
    snprintf(p, sizeof p, "%s/fifo.obj", dir);
    assert_int_equal(lstat(p, &st), 0);
    assert_true(S_ISFIFO(st.st_mode));

    assert_int_equal(run_in(dir, NULL, "atlas in.obj -o folder.obj"), 5);
    assert_no_work(dir);
    snprintf(p, sizeof p, "%s/folder.obj", dir);
    assert_int_equal(lstat(p, &st), 0);
    assert_true(S_ISDIR(st.st_mode));

    /* a device: refused, never replaced by a regular file (as root the
     * rename would succeed) */
    if (stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode)) {
        assert_int_equal(run_in(dir, NULL, "param in.obj -o /dev/full"), 5);
        assert_no_work(dir);
        assert_int_equal(run_in(dir, NULL, "param in.obj -o out.obj --report /dev/full"), 5);
        assert_int_equal(stat("/dev/full", &st), 0);
        assert_true(S_ISCHR(st.st_mode));
        snprintf(p, sizeof p, "%s/out.obj", dir);
        assert_false(test_exists(p));
    }
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void same_file_twice_is_a_usage_error(void **state)
{
    (void)state;
    char dir[512], in[600], p[600];
    make_dir(dir, sizeof dir, "same");
    snprintf(in, sizeof in, "%s/in.obj", dir);
    char *before = test_slurp(in);
    assert_non_null(before);
    assert_int_equal(test_run("cd '%s' && ln -s in.obj alias.obj && ln in.obj hard.obj", dir), 0);
    static const char *const cases[] = {
        "param in.obj -o c.obj --report in.obj",
        "param in.obj -o in.obj",
        "param in.obj -o alias.obj",
        "param in.obj -o hard.obj",
        "param in.obj -o c.obj --svg ./in.obj",
        "atlas in.obj -o a.obj --png in.obj",
        "param in.obj -o x.obj --report x.obj",
        "param in.obj -o x.obj --svg x.obj",
        "atlas in.obj -o x.obj --png sub/../x.obj",
        "param in.obj -o c.obj --report r.json --svg r.json",
    };
    assert_int_equal(test_run("mkdir '%s/sub'", dir), 0);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(run_in(dir, NULL, cases[i]), 2);
        assert_no_work(dir);
        char *e = stderr_of(dir);
        assert_non_null(strstr(e, "same file"));
        free(e);
        assert_file_is(in, before);
    }
    static const char *const never[] = {"c.obj", "a.obj", "x.obj", "r.json"};
    for (size_t i = 0; i < sizeof never / sizeof never[0]; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, never[i]);
        assert_false(test_exists(p));
    }
    free(before);
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void missing_folder_fails_before_any_work(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "nodir");
    assert_int_equal(run_in(dir, NULL, "param in.obj -o nodir/o.obj"), 5);
    assert_no_work(dir);
    assert_int_equal(run_in(dir, NULL, "param in.obj -o o.obj --report nodir/r.json"), 5);
    assert_no_work(dir);
    char *e = stderr_of(dir);
    assert_non_null(strstr(e, "nodir/r.json"));
    free(e);
    assert_int_equal(run_in(dir, NULL, "atlas in.obj -o o.obj --svg nodir/s.svg"), 5);
    assert_no_work(dir);
    snprintf(p, sizeof p, "%s/o.obj", dir);
    assert_false(test_exists(p)); /* the OBJ is not written either */
    /* a folder where no file can be created (proc), found by trying */
    struct stat st;
    if (stat("/proc/self", &st) == 0) {
        assert_int_equal(run_in(dir, NULL, "param in.obj -o o.obj --svg /proc/scaf_test.svg"), 5);
        assert_no_work(dir);
        assert_false(test_exists(p));
    }
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void extension_decides_the_format(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "ext");
    static const char *const refused[] = {"param in.obj -o ch.off",    "atlas in.obj -o ch.stl",
                                          "param in.obj -o ch.off.gz", "param in.obj -o ch.mesh",
                                          "gen hemisphere -o ch.off",  "gen hemisphere -o ch.ply"};
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        assert_int_equal(run_in(dir, NULL, refused[i]), 2);
        assert_no_work(dir);
        char *e = stderr_of(dir);
        assert_non_null(strstr(e, "name the output .obj or "));
        free(e);
    }
    assert_int_equal(test_run("ls '%s' | grep -q '^ch'", dir), 1);

    assert_int_equal(
        run_in(dir, NULL, "param in.obj -o out.obj.gz -q --iterations 2 --report r.json.gz"), 0);
    snprintf(p, sizeof p, "%s/out.obj.gz", dir);
    FILE *f = fopen(p, "rb");
    assert_non_null(f);
    unsigned char magic[2] = {0, 0};
    assert_int_equal(fread(magic, 1, 2, f), 2);
    fclose(f);
    assert_int_equal(magic[0], 0x1f);
    assert_int_equal(magic[1], 0x8b);
    assert_int_equal(test_run("cd '%s' && %s info out.obj.gz > /dev/null && %s check out.obj.gz > "
                              "/dev/null",
                              dir, SCAF_BINARY, SCAF_BINARY),
                     0);
    assert_int_equal(test_run("cd '%s' && gzip -dc r.json.gz | grep -q '\"iterations\"'", dir), 0);
    /* the same map as the plain OBJ */
    assert_int_equal(run_in(dir, NULL, "param in.obj -o out.obj -q --iterations 2"), 0);
    assert_int_equal(test_run("cd '%s' && gzip -dc out.obj.gz | cmp -s - out.obj", dir), 0);
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void dash_is_standard_output(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "dash");
    assert_int_equal(test_run("mkdir '%s/tmp'", dir), 0);
    assert_int_equal(run_in(dir, "TMPDIR=tmp", "param in.obj -o - -q --iterations 2 > piped.obj"),
                     0);
    assert_int_equal(test_run("cd '%s' && %s check piped.obj > /dev/null", dir, SCAF_BINARY), 0);
    assert_int_equal(run_in(dir, "TMPDIR=tmp",
                            "atlas in.obj -o a.obj --report - -q --iterations 2 "
                            "--compact-iterations 2 > report.json"),
                     0);
    assert_int_equal(
        test_run("cd '%s' && grep -q '\"command\": \"atlas\"' report.json && test -s a.obj", dir),
        0);
    assert_int_equal(run_in(dir, NULL, "param in.obj -o - --report - > none.txt"), 2);
    /* an empty name is a bad command line (it was exit 5, a failed write) */
    static const char *const empty[][2] = {
        {"param in.obj -o ''", "-o: the file name is empty"},
        {"param in.obj -o o.obj --report ''", "--report: the file name is empty"},
        {"gen hemisphere -o ''", "-o: the file name is empty"},
        {"atlas in.obj -o '' -q", "-o: the file name is empty"}};
    for (size_t i = 0; i < sizeof empty / sizeof empty[0]; i++) {
        assert_int_equal(run_in(dir, NULL, empty[i][0]), 2);
        char *e = stderr_of(dir);
        assert_non_null(strstr(e, empty[i][1]));
        free(e);
    }
    assert_no_work(dir);
    snprintf(p, sizeof p, "%s/none.txt", dir);
    assert_file_is(p, "");
    snprintf(p, sizeof p, "%s/-", dir);
    assert_false(test_exists(p)); /* never a file named "-" */
    assert_int_equal(test_run("test -z \"$(ls -A '%s/tmp')\"", dir), 0);
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void failed_write_commits_nothing(void **state)
{
    (void)state;
    char dir[512], p[600], q[600];
    make_dir(dir, sizeof dir, "fsize");
    snprintf(p, sizeof p, "%s/out.obj", dir);
    snprintf(q, sizeof q, "%s/r.json", dir);
    write_text(p, "old mesh\n");
    write_text(q, "old report\n");
    /* files up to 6 KiB: the OBJ (~5 KB) fits, the SVG with its scaffold
     * (~10 KB) does not. Control: the OBJ alone is written. */
    const char *limit = "bash -c \"ulimit -f 6; trap '' XFSZ; exec \\\"\\$0\\\" \\\"\\$@\\\"\"";
    assert_int_equal(run_in(dir, limit, "param in.obj -o alone.obj -q --iterations 3"), 0);
    assert_int_equal(run_in(dir, limit,
                            "param in.obj -o out.obj --report r.json --svg s.svg --svg-scaffold -q "
                            "--iterations 3"),
                     5);
    char *e = stderr_of(dir);
    assert_non_null(strstr(e, "s.svg"));
    assert_non_null(strstr(e, "nothing written"));
    free(e);
    assert_file_is(p, "old mesh\n");
    assert_file_is(q, "old report\n");
    snprintf(p, sizeof p, "%s/s.svg", dir);
    assert_false(test_exists(p));
    assert_int_equal(hidden_files(dir), 0);
    remove_dir(dir);
}

static void file_size_limit_is_a_failed_write(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "xfsz");
    snprintf(p, sizeof p, "%s/out.obj", dir);
    write_text(p, "old mesh\n");
    /* 3 KiB per file: the input (2.7 KB) was written before; the output
     * (~5 KB, and its .gz staging) is not. SIGXFSZ is left as the shell
     * has it (its default ends the program). */
    const char *limit = "bash -c \"ulimit -f 3; exec \\\"\\$0\\\" \\\"\\$@\\\"\"";
    static const char *const runs[] = {"param in.obj -o out.obj -q --iterations 2",
                                       "param in.obj -o out.obj.gz -q --iterations 2",
                                       "gen hemisphere --size 6 -o out.obj"};
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        assert_int_equal(run_in(dir, limit, runs[i]), 5);
        char *e = stderr_of(dir);
        assert_non_null(strstr(e, "out.obj"));
        assert_non_null(strstr(e, "nothing written"));
        free(e);
        assert_file_is(p, "old mesh\n");
        assert_int_equal(hidden_files(dir), 0);
    }
    remove_dir(dir);
}

static void signal_stops_cleanly_with_exit_8(void **state)
{
    (void)state;
    char dir[512], p[600], q[600];
    make_dir(dir, sizeof dir, "signal");
    snprintf(p, sizeof p, "%s/out.obj", dir);
    snprintf(q, sizeof q, "%s/r.json", dir);
    write_text(p, "old mesh\n");
    /* the hook, the command, the signal the message names (the first) */
    static const char *const runs[][3] = {
        {"SCAF_TEST_RAISE_SIGNAL_AT=2",
         "param in.obj -o out.obj --report r.json --tolerance 0 --iterations 20", "SIGINT"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=2:TERM",
         "param in.obj -o out.obj --tolerance 0 --iterations 20", "SIGTERM"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=write",
         "param in.obj -o out.obj --report r.json --svg s.svg --png p.png "
         "--iterations 2",
         "SIGINT"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=write:TERM",
         "param in.obj -o out.obj.gz --report r.json --iterations 2", "SIGTERM"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=3", "atlas in.obj -o out.obj --report r.json --iterations 5",
         "SIGINT"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=write",
         "atlas in.obj -o out.obj --report r.json --svg s.svg --iterations 2 "
         "--compact-iterations 2",
         "SIGINT"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=write", "gen hemisphere -o out.obj", "SIGINT"},
        /* a second Ctrl-C, a SIGHUP (the terminal closed), both: the same
         * clean end (it used to kill the program: exit 130 / 129 and the
         * temporary files left) */
        {"SCAF_TEST_RAISE_SIGNAL_AT=write:INT:INT",
         "param in.obj -o out.obj.gz --report r.json --iterations 2", "SIGINT"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=write:HUP",
         "param in.obj -o out.obj.gz --report r.json --iterations 2", "SIGHUP"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=2:HUP:INT:TERM",
         "atlas in.obj -o out.obj --report r.json --iterations 5", "SIGHUP"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=write:INT:INT:INT", "gen hemisphere -o out.obj.gz", "SIGINT"},
    };
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        assert_int_equal(run_in(dir, runs[i][0], runs[i][1]), 8);
        char *e = stderr_of(dir);
        const char *line = strstr(e, "interrupted by SIG");
        assert_non_null(line);
        assert_non_null(strstr(line, runs[i][2]));
        assert_null(strstr(e, "internal error"));
        free(e);
        assert_file_is(p, "old mesh\n");
        assert_false(test_exists(q));
        assert_int_equal(hidden_files(dir), 0);
    }
    assert_int_equal(
        test_run("ls '%s' | grep -qv -e '^in.obj$' -e '^out.obj$' -e '^err.txt$'", dir), 1);
    /* the hook at an iteration the run never reaches: a normal run */
    assert_int_equal(
        run_in(dir, "SCAF_TEST_RAISE_SIGNAL_AT=999", "param in.obj -o out.obj -q --iterations 2"),
        0);
    remove_dir(dir);
}

/* issue 29: the phases without iterations listen too. The hook raises
 * the signal as the phase starts (setup: the charts' start; analysis: the
 * solver's first analysis; pack: the raster packer; parse: reading the
 * input, which looks every 65536 lines); the phase itself must stop:
 * exit 8, the message names the phase where it says so, nothing written
 * (atlas on 1,000,000 charts ignored SIGTERM for 43 s). */
static void long_phases_stop_at_a_signal(void **state)
{
    (void)state;
    char dir[512], p[600];
    make_dir(dir, sizeof dir, "phases");
    assert_int_equal(test_run("%s gen grid --size 200 -o %s/big.obj", SCAF_BINARY, dir), 0);
    snprintf(p, sizeof p, "%s/out.obj", dir);
    write_text(p, "old mesh\n");
    static const char *const runs[][3] = {
        {"SCAF_TEST_RAISE_SIGNAL_AT=setup:TERM", "atlas in.obj -o out.obj --iterations 3",
         "interrupted by SIGTERM"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=setup:HUP", "param in.obj -o out.obj --iterations 3",
         "interrupted by SIGHUP"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=analysis", "atlas in.obj -o out.obj --iterations 3",
         "interrupted by SIGINT"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=analysis:TERM", "param in.obj -o out.obj --iterations 3",
         "interrupted by SIGTERM"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=pack:TERM",
         "atlas in.obj -o out.obj --iterations 3 --compact-iterations 2", "interrupted by SIGTERM"},
        {"SCAF_TEST_RAISE_SIGNAL_AT=parse:TERM", "param big.obj -o out.obj --iterations 3",
         "interrupted by SIGTERM while reading the mesh; nothing written"},
    };
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        assert_int_equal(run_in(dir, runs[i][0], runs[i][1]), 8);
        char *e = stderr_of(dir);
        if (!strstr(e, runs[i][2])) fprintf(stderr, "%s: %s\n", runs[i][1], e);
        assert_non_null(strstr(e, runs[i][2]));
        assert_null(strstr(e, "iterations, E")); /* no iteration ran to its end */
        free(e);
        if (i < 2 || i == 5) assert_no_work(dir); /* stopped before its first line */
        assert_file_is(p, "old mesh\n");
        assert_int_equal(hidden_files(dir), 0);
    }
    remove_dir(dir);
}

static void help_lists_exit_8(void **state)
{
    (void)state;
    static const char *const cmds[] = {"param", "atlas"};
    for (size_t i = 0; i < 2; i++) {
        char dir[512];
        make_dir(dir, sizeof dir, cmds[i]);
        char args[64];
        snprintf(args, sizeof args, "%s --help > help.txt", cmds[i]);
        assert_int_equal(run_in(dir, NULL, args), 0);
        assert_int_equal(test_run("grep -Eq '^ *8 +interrupted' '%s/help.txt'", dir), 0);
        assert_int_equal(test_run("grep -q 'written together' '%s/help.txt'", dir), 0);
        remove_dir(dir);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(symlink_output_is_written_through),
        cmocka_unit_test(fifo_device_and_directory_are_refused),
        cmocka_unit_test(same_file_twice_is_a_usage_error),
        cmocka_unit_test(missing_folder_fails_before_any_work),
        cmocka_unit_test(extension_decides_the_format),
        cmocka_unit_test(dash_is_standard_output),
        cmocka_unit_test(failed_write_commits_nothing),
        cmocka_unit_test(file_size_limit_is_a_failed_write),
        cmocka_unit_test(signal_stops_cleanly_with_exit_8),
        cmocka_unit_test(long_phases_stop_at_a_signal),
        cmocka_unit_test(help_lists_exit_8),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
