/* mesh/write_ply: writing a mesh as binary PLY with per-corner UVs, atomically.
 *
 * Binary little endian (exact and compact: the doubles scaf computed are
 * written as they are, so `scaf check` of the file proves what the atlas
 * proved): `vertex` with double x, y, z; `face` with
 * `list uchar int vertex_indices` and, when the mesh has UVs,
 * `list uchar double texcoord` (u v for each of the 3 corners), the
 * per-corner convention Blender and MeshLab read, so a UV seam is simply
 * two corners of one vertex with different texcoords. Fails like
 * mesh_write_obj: SCAF_ERR_MESH for an invalid mesh (nothing written),
 * SCAF_ERR_IO naming the path.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "mesh/mesh_io.h"

static void put_u32(unsigned char *b, uint32_t x)
{
    for (int k = 0; k < 4; k++) b[k] = (unsigned char)(x >> (8 * k));
}

static void put_f64(unsigned char *b, double d)
{
    uint64_t x;
    memcpy(&x, &d, 8);
    for (int k = 0; k < 8; k++) b[k] = (unsigned char)(x >> (8 * k));
}

static scaf_status check_mesh(const mesh *m, scaf_error *err)
{
    int uv = mesh_has_uv(m);
    if (m->nv < 0 || m->nf < 0 || (m->nv > 0 && !m->V) || (m->nf > 0 && !m->F) || (uv && !m->UV))
        return err_set(err, SCAF_ERR_MESH, "mesh_write_ply: inconsistent mesh arrays");
    for (size_t k = 0; k < 3 * (size_t)m->nv; k++)
        if (!isfinite(m->V[k]))
            return err_set(err, SCAF_ERR_MESH,
                           "mesh_write_ply: vertex %zu has a non-finite coordinate", k / 3);
    for (size_t k = 0; k < 3 * (size_t)m->nf; k++) {
        if (m->F[k] < 0 || m->F[k] >= m->nv)
            return err_set(err, SCAF_ERR_MESH, "mesh_write_ply: face %zu uses vertex %d of %d",
                           k / 3, m->F[k], m->nv);
        if (uv &&
            (m->FT[k] < 0 || m->FT[k] >= m->nuv || !isfinite(m->UV[2 * (size_t)m->FT[k]]) ||
             !isfinite(m->UV[2 * (size_t)m->FT[k] + 1])))
            return err_set(err, SCAF_ERR_MESH,
                           "mesh_write_ply: face %zu has a UV out of range or not finite", k / 3);
    }
    return SCAF_OK;
}

static int write_body(FILE *f, const mesh *m)
{
    int uv = mesh_has_uv(m);
    if (fprintf(f,
                "ply\nformat binary_little_endian 1.0\ncomment written by scaf %s\n"
                "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
                "element face %d\nproperty list uchar int vertex_indices\n%s"
                "end_header\n",
                scaf_version(), m->nv, m->nf,
                uv ? "property list uchar double texcoord\n" : "") < 0)
        return -1;
    unsigned char b[1 + 12 + 1 + 48];
    for (int i = 0; i < m->nv; i++) {
        for (int k = 0; k < 3; k++) put_f64(b + 8 * k, m->V[3 * (size_t)i + (size_t)k]);
        if (fwrite(b, 1, 24, f) != 24) return -1;
    }
    for (int i = 0; i < m->nf; i++) {
        size_t n = 0;
        b[n++] = 3;
        for (int k = 0; k < 3; k++, n += 4)
            put_u32(b + n, (uint32_t)m->F[3 * (size_t)i + (size_t)k]);
        if (uv) {
            b[n++] = 6;
            for (int k = 0; k < 3; k++) {
                const double *t = m->UV + 2 * (size_t)m->FT[3 * (size_t)i + (size_t)k];
                put_f64(b + n, t[0]);
                put_f64(b + n + 8, t[1]);
                n += 16;
            }
        }
        if (fwrite(b, 1, n, f) != n) return -1;
    }
    return ferror(f) ? -1 : 0;
}

scaf_status mesh_write_ply(const char *path, const mesh *m, scaf_error *err)
{
    if (!path || !*path || !m)
        return err_set(err, SCAF_ERR_USAGE, "mesh_write_ply: no path or mesh");
    scaf_status st = check_mesh(m, err);
    if (st) {
        err_prefix(err, "%s: not written", path);
        return st;
    }
    atomic_file af;
    st = atomic_open(&af, path, err);
    if (st) return st;
    static const size_t bufsize = 1 << 20;
    char *buf = malloc(bufsize);
    if (buf) setvbuf(af.f, buf, _IOFBF, bufsize);
    if (write_body(af.f, m) != 0) {
        atomic_abort(&af);
        free(buf);
        return err_set(err, SCAF_ERR_IO, "%s: cannot write (disk full?)", path);
    }
    st = atomic_commit(&af, err);
    free(buf);
    return st;
}
