/* Tests of base/atomic_file: what "the target" of a write is, and the
 * two-phase commit.
 *
 * In a fresh folder: a symbolic link (relative, in a subfolder, chained,
 * dangling) is written through and stays a link; a link loop, a FIFO, a
 * directory, a missing folder and a name ending in '/' are refused with
 * SCAF_ERR_IO naming the path and nothing is created; a replaced file
 * keeps its permission bits; atomic_finish keeps the data under the
 * temporary name (the target unchanged) until atomic_rename, and
 * atomic_abort after atomic_finish removes it. */
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

#include "base/atomic_file.h"
#include "support/support.h"

static char dir[512];

static int setup(void **state)
{
    (void)state;
    char base[256];
    test_tmp_path("", base, sizeof base);
    int n = snprintf(dir, sizeof dir, "%satomic_file_XXXXXX", base);
    if (n < 0 || (size_t)n >= sizeof dir || !mkdtemp(dir)) return -1;
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    test_run("rm -rf '%s'", dir);
    return 0;
}

static const char *at(const char *name, char *buf, size_t size)
{
    snprintf(buf, size, "%s/%s", dir, name);
    return buf;
}

static int entries(void)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
    closedir(d);
    return n;
}

static scaf_status write_text(const char *path, const char *text, scaf_error *err)
{
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    fputs(text, a.f);
    return atomic_commit(&a, err);
}

static void assert_text(const char *path, const char *text)
{
    char *s = test_slurp(path);
    assert_non_null(s);
    assert_string_equal(s, text);
    free(s);
}

static void assert_link(const char *path)
{
    struct stat st;
    assert_int_equal(lstat(path, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
}

static void links_are_written_through(void **state)
{
    (void)state;
    char p[600], q[600];
    scaf_error err;
    assert_int_equal(test_run("cd '%s' && mkdir sub && echo old > sub/t.txt && ln -s sub/t.txt l1 "
                              "&& ln -s l1 l2 "
                              "&& ln -s ../new.txt sub/dangling && ln -s \"$PWD/sub/t.txt\" abs",
                              dir),
                     0);
    assert_int_equal(write_text(at("l2", p, sizeof p), "via chain\n", &err), SCAF_OK);
    assert_link(p);
    assert_link(at("l1", p, sizeof p));
    assert_text(at("sub/t.txt", q, sizeof q), "via chain\n");
    assert_int_equal(write_text(at("abs", p, sizeof p), "via absolute\n", &err), SCAF_OK);
    assert_link(p);
    assert_text(q, "via absolute\n");
    assert_int_equal(write_text(at("sub/dangling", p, sizeof p), "created\n", &err), SCAF_OK);
    assert_link(p);
    assert_text(at("new.txt", q, sizeof q), "created\n");
    /* the resolved target is absolute and canonical */
    char r[4096];
    int exists = -1;
    assert_int_equal(atomic_resolve(at("sub/../l2", p, sizeof p), r, sizeof r, &exists, &err),
                     SCAF_OK);
    assert_int_equal(exists, 1);
    assert_int_equal(r[0], '/');
    assert_non_null(strstr(r, "/sub/t.txt"));
    assert_null(strstr(r, ".."));
    assert_int_equal(entries(), 5); /* sub, l1, l2, abs, new.txt: no temporary file */
}

static void non_regular_targets_are_refused(void **state)
{
    (void)state;
    char p[600];
    scaf_error err;
    assert_int_equal(test_run("cd '%s' && mkfifo fifo && mkdir folder && ln -s loop_b loop_a && ln "
                              "-s loop_a loop_b "
                              "&& ln -s folder to_folder",
                              dir),
                     0);
    int before = entries();
    static const char *const refused[][2] = {
        {"fifo", "FIFO"},       {"folder", "directory"},     {"to_folder", "directory"},
        {"loop_a", "symbolic"}, {"missing/x.txt", "folder"}, {"folder/", "directory"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        err.message[0] = '\0';
        assert_int_equal(write_text(at(refused[i][0], p, sizeof p), "x\n", &err), SCAF_ERR_IO);
        assert_non_null(strstr(err.message, refused[i][0]));
        assert_non_null(strstr(err.message, refused[i][1]));
    }
    if (access("/dev/null", W_OK) == 0) {
        assert_int_equal(write_text("/dev/null", "x\n", &err), SCAF_ERR_IO);
        assert_non_null(strstr(err.message, "device"));
    }
    assert_int_equal(entries(), before);
    struct stat st;
    assert_int_equal(lstat(at("fifo", p, sizeof p), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
}

static void replaced_file_keeps_its_mode(void **state)
{
    (void)state;
    char p[600];
    scaf_error err;
    assert_int_equal(write_text(at("m.txt", p, sizeof p), "one\n", &err), SCAF_OK);
    struct stat st;
    assert_int_equal(stat(p, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0644);
    assert_int_equal(chmod(p, 0600), 0);
    assert_int_equal(write_text(p, "two\n", &err), SCAF_OK);
    assert_int_equal(stat(p, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0600);
    assert_text(p, "two\n");
}

static void finish_then_rename_or_abort(void **state)
{
    (void)state;
    char p[600], q[600];
    scaf_error err;
    assert_int_equal(write_text(at("a.txt", p, sizeof p), "old a\n", &err), SCAF_OK);
    atomic_file a, b;
    assert_int_equal(atomic_open(&a, p, &err), SCAF_OK);
    assert_int_equal(atomic_open(&b, at("b.txt", q, sizeof q), &err), SCAF_OK);
    fputs("new a\n", a.f);
    fputs("new b\n", b.f);
    assert_int_equal(atomic_finish(&a, &err), SCAF_OK);
    assert_int_equal(atomic_finish(&b, &err), SCAF_OK);
    assert_text(p, "old a\n"); /* nothing visible before the renames */
    assert_false(test_exists(q));
    assert_text(a.tmp, "new a\n");
    assert_int_equal(atomic_rename(&a, &err), SCAF_OK);
    atomic_abort(&b); /* b given up after finishing: its temporary file goes */
    assert_text(p, "new a\n");
    assert_false(test_exists(q));
    atomic_abort(&a); /* after a commit: nothing to do */
    assert_text(p, "new a\n");
    assert_int_equal(entries(), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(links_are_written_through, setup, teardown),
        cmocka_unit_test_setup_teardown(non_regular_targets_are_refused, setup, teardown),
        cmocka_unit_test_setup_teardown(replaced_file_keeps_its_mode, setup, teardown),
        cmocka_unit_test_setup_teardown(finish_then_rename_or_abort, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
