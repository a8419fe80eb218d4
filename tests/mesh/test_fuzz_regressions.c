/* Inputs kept from fuzzing: every file in fuzz/regressions/ (inputs that once
 * crashed or misbehaved) must give a clean error or a consistent mesh, and
 * every seed in fuzz/corpus/ must parse. The files use the fuzz target's
 * layout: the first byte picks the format (0 OBJ, 1 OFF, 2 PLY, 3 guess). */
#include <dirent.h>
#include <math.h>

#include "mesh_test_util.h"

/* The repository root, from this file's compiled path. */
static void repo_path(const char *rel, char *buf, size_t size)
{
    snprintf(buf, size, "%s", __FILE__);
    for (int up = 0; up < 3; up++) {
        char *s = strrchr(buf, '/');
        if (s) *s = '\0';
    }
    size_t n = strlen(buf);
    snprintf(buf + n, size - n, "/%s", rel);
}

/* Parse one stored input; returns the status after checking consistency. */
static scaf_status check_input(const char *path)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    static unsigned char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    if (n < 1) return SCAF_OK;
    static const mesh_format formats[4] = {MESH_FORMAT_OBJ, MESH_FORMAT_OFF, MESH_FORMAT_PLY,
                                           MESH_FORMAT_UNKNOWN};
    /* Copy to an exact-size block so ASan catches any overread. */
    char *data = malloc(n - 1 ? n - 1 : 1);
    assert_non_null(data);
    memcpy(data, buf + 1, n - 1);
    mesh m;
    scaf_error e;
    err_clear(&e);
    scaf_status s = mesh_parse(data, n - 1, formats[buf[0] % 4], path, &m, NULL, &e);
    free(data);
    if (s != SCAF_OK) {
        assert_null(m.V);
        assert_true(e.message[0] != '\0');
        return s;
    }
    assert_true(m.nf > 0);
    for (size_t k = 0; k < 3 * (size_t)m.nv; k++) assert_true(isfinite(m.V[k]));
    for (size_t k = 0; k < 3 * (size_t)m.nf; k++) {
        assert_true(m.F[k] >= 0 && m.F[k] < m.nv);
        if (m.FT) assert_true(m.FT[k] >= 0 && m.FT[k] < m.nuv);
    }
    mesh_free(&m);
    return SCAF_OK;
}

static int for_each_file(const char *rel, int must_parse)
{
    char dir[1024], path[1400];
    repo_path(rel, dir, sizeof dir);
    DIR *d = opendir(dir);
    if (!d) return 0;
    int count = 0;
    struct dirent *ent;
    while ((ent = readdir(d)) != NULL) {
        size_t len = strlen(ent->d_name);
        if (ent->d_name[0] == '.' || (len > 3 && strcmp(ent->d_name + len - 3, ".md") == 0))
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, ent->d_name);
        scaf_status s = check_input(path);
        if (must_parse && s != SCAF_OK) print_error("seed %s does not parse\n", path);
        if (must_parse) assert_int_equal(s, SCAF_OK);
        count++;
    }
    closedir(d);
    return count;
}

static void regressions_fail_cleanly(void **state)
{
    (void)state;
    print_message("%d regression inputs\n", for_each_file("fuzz/regressions", 0));
}

static void seed_corpus_parses(void **state)
{
    (void)state;
    if (for_each_file("fuzz/corpus", 1) == 0) skip();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(regressions_fail_cleanly),
        cmocka_unit_test(seed_corpus_parses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
