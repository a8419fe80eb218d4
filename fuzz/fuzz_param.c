/* fuzz/fuzz_param: libFuzzer target for the whole optimizer on tiny meshes.
 *
 * The input is a compact binary mesh, so the fuzzer explores geometry and
 * connectivity rather than text syntax (fuzz_mesh_parse does that):
 *   byte 0       vertex count 3 + b % 30
 *   byte 1       face count 1 + b % 48
 *   byte 2       flags: bit 0 harmonic start, bits 1-2 energy, bit 3 the
 *                atlas instead of param, bit 4 UVs from the data too,
 *                bit 5 mean-value start (when bit 0 is clear)
 *   then         per vertex 3 coordinates of 2 bytes (int16 / 256), per
 *                face 3 vertex bytes (mod vertex count), and with bit 4 per
 *                vertex one UV of 2 x 2 bytes, FT = F.
 * Missing bytes read as zero. Seeds: fuzz/corpus_param/ (a 3 x 3 grid as
 * param, as atlas with UVs, as param with UVs). Whatever the mesh, the library must return
 * a status (never crash, hang or leak); when param or the atlas succeeds,
 * the result must be bijective by the exact checker (the atlas' output
 * also certified): anything else aborts.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "app/atlas.h"
#include "app/atlas_output.h"
#include "geom/bijectivity.h"
#include "scaf/scaf.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct reader {
    const uint8_t *p;
    size_t n, i;
} reader;

static unsigned next_byte(reader *r) { return r->i < r->n ? r->p[r->i++] : 0u; }

static double next_coord(reader *r)
{
    unsigned lo = next_byte(r), hi = next_byte(r);
    return (double)(int16_t)(uint16_t)(lo | hi << 8) / 256.0;
}

static void run_param(int nv, const double *V, int nf, const int *F, const double *UV,
                      const int *FT, unsigned flags)
{
    scaf_options_t o = scaf_options_default();
    o.init = flags & 1 ? SCAF_INIT_HARMONIC : flags & 32 ? SCAF_INIT_MVC : SCAF_INIT_TUTTE;
    o.energy = (scaf_energy)((flags >> 1) % 3);
    o.max_iterations = 3;
    scaf_param_t *p = scaf_param_new(&o);
    if (!p) return;
    if (scaf_param_set_mesh(p, V, nv, F, nf, UV, UV ? nv : 0, FT) == SCAF_OK &&
        scaf_param_run(p, 3, NULL, NULL) == SCAF_OK) {
        int nuv = scaf_param_uv_count(p);
        double *uv = malloc(sizeof(double) * 2 * (size_t)nuv);
        int *ft = malloc(sizeof(int) * 3 * (size_t)nf);
        if (uv && ft && scaf_param_get_uv(p, uv, ft) == SCAF_OK) {
            bij_report r;
            scaf_error err;
            /* charts by UV connectivity: NULL lets the checker find them */
            if (bij_check(nuv, uv, nf, ft, NULL, NULL, &r, &err) == SCAF_OK && !r.bijective)
                abort();
        }
        free(uv);
        free(ft);
    }
    scaf_param_destroy(p);
}

static void run_atlas(const double *V, int nv, const int *F, int nf, const double *UV,
                      const int *FT)
{
    mesh m = {nv, (double *)V, nf, (int *)F, UV ? nv : 0, (double *)UV, (int *)FT};
    atlas_options o = atlas_options_default();
    o.padding = 1.0 / 256.0;
    o.settle_iterations = 2;
    o.compact_iterations = 2;
    o.pack_cells = 64;
    atlas a;
    scaf_error err;
    if (atlas_init(&a, &m, &o, &err) != SCAF_OK) return;
    if (atlas_run(&a, NULL, NULL, &err) == SCAF_OK) {
        double *out = malloc(sizeof(double) * 2 * (size_t)a.nw);
        atlas_output ao;
        if (out && atlas_output_verify(&a, out, &ao, &err) == SCAF_ERR_INTERNAL) abort();
        free(out);
    }
    atlas_free(&a);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    reader r = {data, size, 0};
    int nv = 3 + (int)(next_byte(&r) % 30), nf = 1 + (int)(next_byte(&r) % 48);
    unsigned flags = next_byte(&r);
    double V[3 * 32], UV[2 * 32];
    int F[3 * 48];
    for (int i = 0; i < 3 * nv; i++) V[i] = next_coord(&r);
    for (int i = 0; i < 3 * nf; i++) F[i] = (int)(next_byte(&r) % (unsigned)nv);
    int with_uv = (flags >> 4) & 1;
    for (int i = 0; with_uv && i < 2 * nv; i++) UV[i] = next_coord(&r);
    if (flags & 8) run_atlas(V, nv, F, nf, with_uv ? UV : NULL, with_uv ? F : NULL);
    else run_param(nv, V, nf, F, with_uv ? UV : NULL, with_uv ? F : NULL, flags);
    return 0;
}
