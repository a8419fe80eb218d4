/* Reading every mesh of the shared test folder (../shared/data) succeeds
 * with the MANIFEST.md counts; skipped when the folder is absent. The bad/
 * meshes parse too: their defects are topology, not syntax. */
#include <math.h>

#include "mesh_test_util.h"

/* MANIFEST.md counts: F after fan triangulation, V = referenced vertices. */
typedef struct manifest_entry {
    const char *file;
    int v, f;
    int nuv; /* vt count, 0 for none */
} manifest_entry;

static const manifest_entry manifest[] = {
    {"disk/aphrodite.obj", 55598, 110788, 0},
    {"disk/bull_1.obj", 17918, 34504, 0},
    {"disk/camel_b.obj", 2032, 3576, 2032},
    {"disk/camelhead.off", 11381, 22704, 0},
    {"disk/hand_lowres.obj", 810, 1602, 0},
    {"disk/hilbert.obj", 18424, 32228, 0},
    {"disk/mountain.obj", 25600, 50562, 0},
    {"seams/blub.obj", 7106, 14208, 7317},
    {"seams/human_neutral.obj", 10475, 20908, 11437},
    {"seams/myles_eight_seamed.obj", 2488, 4510, 2488},
    {"seams/myles_knot1_seamed.obj", 885, 1474, 885},
    {"seams/spot.obj", 2930, 5856, 3225},
    {"closed/armadillo.obj", 43243, 86482, 0},
    {"closed/bunny.obj", 568, 1132, 0},
    {"closed/bunnyx30.obj", 568, 1132, 0},
    {"closed/fertility.off", 4494, 9000, 0},
    {"closed/leg-flow6.off", 6617, 13230, 0},
    {"closed/leg-intersect.off", 6617, 13230, 0},
    {"closed/nefertiti-lowres.obj", 35002, 70000, 0},
    {"large/aphrodite_subdiv16x.obj.gz", 887117, 1772608, 0},
    {"large/igea.obj", 134345, 268686, 0},
    {"large/nefertiti_subdiv16x.obj.gz", 560002, 1120000, 0},
    {"bad/cow.obj", 2903, 5804, 0},
    {"bad/edge_with_four_triangles.off", 6, 4, 0},
    {"bad/hour_glass.off", 259, 512, 0},
    {"bad/inverted_triangles.obj", 12577, 24685, 0},
    {"bad/plane_holes.obj", 8519, 16747, 0},
    {"bad/stanford-bunny.obj", 34834, 69451, 0},
    {"bad/truck.obj", 2956, 4770, 0},
};

static void shared_meshes_match_manifest(void **state)
{
    (void)state;
    char path[1024];
    if (!test_data_path("MANIFEST.md", path, sizeof path)) skip();
    for (size_t i = 0; i < sizeof manifest / sizeof *manifest; i++) {
        const manifest_entry *t = &manifest[i];
        if (!test_data_path(t->file, path, sizeof path)) {
            print_message("missing %s: not checked\n", t->file);
            continue;
        }
        mesh m;
        scaf_error e;
        scaf_status s = mesh_read(path, &m, NULL, &e);
        if (s != SCAF_OK) print_error("%s\n", e.message);
        assert_int_equal(s, SCAF_OK);
        char *used = calloc((size_t)m.nv, 1);
        assert_non_null(used);
        int referenced = 0;
        for (size_t k = 0; k < 3 * (size_t)m.nf; k++) {
            assert_true(m.F[k] >= 0 && m.F[k] < m.nv);
            if (!used[m.F[k]]) {
                used[m.F[k]] = 1;
                referenced++;
            }
        }
        free(used);
        if (referenced != t->v || m.nf != t->f || m.nuv != t->nuv)
            print_error("%s: V %d F %d vt %d\n", t->file, referenced, m.nf, m.nuv);
        assert_int_equal(referenced, t->v);
        assert_int_equal(m.nf, t->f);
        assert_int_equal(m.nuv, t->nuv);
        for (size_t k = 0; k < 3 * (size_t)m.nv; k++) assert_true(isfinite(m.V[k]));
        mesh_free(&m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(shared_meshes_match_manifest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
