/* Tests for the OBJ writer: bitwise round trips (positions, UVs, seams),
 * short numbers stay short, and failures leave no partial file and the
 * target untouched. */
#include <dirent.h>
#include <math.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mesh_test_util.h"
#include "mesh/text_scan.h"

static void roundtrip(const mesh *a, const char *name)
{
    char path[512];
    test_tmp_path(name, path, sizeof path);
    scaf_error e;
    scaf_status s = mesh_write_obj(path, a, &e);
    if (s) print_error("%s\n", e.message);
    assert_int_equal(s, SCAF_OK);
    mesh b;
    s = mesh_read(path, &b, NULL, &e);
    if (s) print_error("%s\n", e.message);
    assert_int_equal(s, SCAF_OK);
    assert_same_mesh(a, &b);
    mesh_free(&b);
}

/* Doubles of every kind: random bit patterns (finite), tiny, huge, -0. */
static void random_values_roundtrip_bitwise(void **state)
{
    (void)state;
    mesh m;
    scaf_error e;
    const int nv = 2000, nf = 1000, nuv = 1500;
    assert_int_equal(mesh_alloc(&m, nv, nf, nuv, &e), SCAF_OK);
    uint64_t x = 0x9E3779B97F4A7C15ULL;
    for (int i = 0; i < 3 * nv; i++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        double d;
        if (i % 3 == 0) {
            uint64_t bits = x;
            memcpy(&d, &bits, sizeof d);
            if (!isfinite(d)) d = 1.0 / 3.0;
        } else {
            d = ((double)(x >> 11) / 9007199254740992.0 - 0.5) * pow(10.0, (double)(i % 40) - 20);
        }
        m.V[i] = d;
    }
    m.V[0] = -0.0;
    m.V[1] = 4.9e-324;
    m.V[2] = 1.7976931348623157e308;
    for (int i = 0; i < 2 * nuv; i++) m.UV[i] = m.V[i] * 0.5;
    for (int i = 0; i < nf; i++)
        for (int k = 0; k < 3; k++) {
            m.F[3 * i + k] = (i * 7 + k * 13) % nv;
            m.FT[3 * i + k] = (i * 11 + k * 5) % nuv;
        }
    roundtrip(&m, "write_random.obj");
    mesh_free(&m);
}

static void short_numbers_stay_short(void **state)
{
    (void)state;
    mesh m;
    parse_ok("v 0.1 -2.5 1e-7\nv 1 0 0\nv 0 1 0\nvt 0.25 0.75\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n",
             MESH_FORMAT_OBJ, &m, NULL);
    char path[512];
    test_tmp_path("write_short.obj", path, sizeof path);
    scaf_error e;
    assert_int_equal(mesh_write_obj(path, &m, &e), SCAF_OK);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    char buf[1024];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    assert_non_null(strstr(buf, "scaf"));
    assert_non_null(strstr(buf, "\nv 0.1 -2.5 1e-07\n"));
    assert_non_null(strstr(buf, "\nvt 0.25 0.75\n"));
    assert_non_null(strstr(buf, "\nf 1/1 2/2 3/3\n"));
    mesh_free(&m);
}

/* The number printer gives the fewest of 15, 16, 17 digits that read
 * back bitwise: the same text as trying 15, 16, 17 in turn with strtod as
 * the reader, on values of every kind (numbers short in decimal, 1/3-like
 * ones, random bits, both ends of the range, -0), and so does the hinted
 * printer from any start, which reports the digits the number needed. */
static void numbers_print_shortest(void **state)
{
    (void)state;
    uint64_t x = 0x2545F4914F6CDD1DULL;
    int by_digits[18] = {0};
    for (int i = 0; i < 200000; i++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        double d;
        if (i % 4 == 0) {
            memcpy(&d, &x, sizeof d);
            if (!isfinite(d)) continue;
        } else if (i % 4 == 1) {
            d = (double)(x % 100000) / 1000.0; /* short in decimal */
        } else {
            d = ((double)(x >> 11) / 9007199254740992.0 - 0.5) * pow(10.0, (double)(i % 60) - 30);
        }
        if (i == 0) d = -0.0;
        if (i == 1) d = 4.9e-324;
        if (i == 2) d = 1.7976931348623157e308;
        char got[40], want[40], hinted[40];
        int n = scan_format_double(got, sizeof got, d), prec = 15;
        for (; prec <= 17; prec++) {
            snprintf(want, sizeof want, "%.*g", prec, d);
            if (strtod(want, NULL) == d && signbit(strtod(want, NULL)) == signbit(d)) break;
        }
        assert_true(prec <= 17);
        assert_string_equal(got, want);
        assert_int_equal(n, (int)strlen(want));
        for (int start = 15; start <= 17; start++) { /* any start: the same text */
            int digits = start;
            assert_int_equal(scan_format_double_hint(hinted, sizeof hinted, d, &digits), n);
            assert_string_equal(hinted, want);
            assert_int_equal(digits, prec);
        }
        by_digits[prec]++;
    }
    for (int p = 15; p <= 17; p++) assert_true(by_digits[p] > 0); /* every branch taken */
}

static void seams_roundtrip(void **state)
{
    (void)state;
    mesh m;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 5 5\nvt 6 6\nvt 7 7\n"
             "f 1/1 2/2 3/3\nf 2/4 4/5 3/6\n",
             MESH_FORMAT_OBJ, &m, NULL);
    roundtrip(&m, "write_seams.obj");
    mesh_free(&m);
}

static void shared_meshes_roundtrip(void **state)
{
    (void)state;
    const char *files[] = {"seams/spot.obj", "seams/human_neutral.obj", "disk/camel_b.obj",
                           "disk/camelhead.off", "bad/stanford-bunny.obj"};
    int any = 0;
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        char path[1024];
        if (!test_data_path(files[i], path, sizeof path)) continue;
        any = 1;
        mesh m;
        scaf_error e;
        assert_int_equal(mesh_read(path, &m, NULL, &e), SCAF_OK);
        roundtrip(&m, "write_shared.obj");
        mesh_free(&m);
    }
    if (!any) skip();
}

/* No ".NAME.tmp*" file left in the scratch folder. */
static void assert_no_temp_left(const char *base)
{
    char dir[512];
    test_tmp_path("", dir, sizeof dir);
    DIR *d = opendir(dir);
    assert_non_null(d);
    char prefix[256];
    snprintf(prefix, sizeof prefix, ".%s.tmp", base);
    struct dirent *ent;
    while ((ent = readdir(d)) != NULL) {
        if (strncmp(ent->d_name, prefix, strlen(prefix)) == 0)
            print_error("left over: %s\n", ent->d_name);
        assert_false(strncmp(ent->d_name, prefix, strlen(prefix)) == 0);
    }
    closedir(d);
}

static void invalid_mesh_leaves_target_untouched(void **state)
{
    (void)state;
    char path[512];
    const char *old = "old content\n";
    write_tmp("write_keep.obj", old, strlen(old), path, sizeof path);
    mesh m;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MESH_FORMAT_OBJ, &m, NULL);
    scaf_error e;
    m.F[1] = 7; /* out of range */
    assert_int_equal(mesh_write_obj(path, &m, &e), SCAF_ERR_MESH);
    assert_non_null(strstr(e.message, path));
    m.F[1] = 1;
    m.V[4] = NAN;
    assert_int_equal(mesh_write_obj(path, &m, &e), SCAF_ERR_MESH);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    char buf[64] = {0};
    assert_int_equal(fread(buf, 1, sizeof buf - 1, f), strlen(old));
    fclose(f);
    assert_string_equal(buf, old);
    assert_no_temp_left("write_keep.obj");
    mesh_free(&m);
}

static void io_failures_leave_nothing(void **state)
{
    (void)state;
    mesh m;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MESH_FORMAT_OBJ, &m, NULL);
    scaf_error e;
    /* Folder does not exist. */
    char path[512];
    test_tmp_path("no-such-folder/out.obj", path, sizeof path);
    assert_int_equal(mesh_write_obj(path, &m, &e), SCAF_ERR_IO);
    assert_non_null(strstr(e.message, "no-such-folder/out.obj"));
    /* Target is a folder: the rename fails after writing; the temp file goes. */
    test_tmp_path("write_dir_target", path, sizeof path);
    mkdir(path, 0755);
    assert_int_equal(mesh_write_obj(path, &m, &e), SCAF_ERR_IO);
    assert_non_null(strstr(e.message, "write_dir_target"));
    assert_no_temp_left("write_dir_target");
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_values_roundtrip_bitwise),
        cmocka_unit_test(short_numbers_stay_short),
        cmocka_unit_test(numbers_print_shortest),
        cmocka_unit_test(seams_roundtrip),
        cmocka_unit_test(shared_meshes_roundtrip),
        cmocka_unit_test(invalid_mesh_leaves_target_untouched),
        cmocka_unit_test(io_failures_leave_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
