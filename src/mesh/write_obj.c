/* mesh/write_obj: writing a mesh as OBJ, atomically.
 *
 * Output: one comment line naming scaf, `v x y z` for every vertex in
 * order, `vt u v` for every UV when the mesh has them, then `f a/t b/t c/t`
 * (or `f a b c`), 1-based; with face groups (mesh_write_obj_grouped), a
 * line `g chart_N` before the first face and before every face whose
 * group N differs from the previous face's. Each number is printed with the fewest of 15,
 * 16 or 17 significant digits that reads back to the same double, so a
 * read-write-read cycle is bitwise exact and short inputs stay short.
 *
 * The file is written to a fresh temporary file in the target's folder,
 * flushed and synced, then renamed over the target; on any failure the
 * temporary file is removed and the target is untouched. Fails with
 * SCAF_ERR_MESH for invalid meshes (index out of range, NaN/inf values;
 * nothing is written) and SCAF_ERR_IO naming the path otherwise.
 */
#include "mesh/mesh_io.h"
#include "base/atomic_file.h"
#include "mesh/text_scan.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static scaf_status check_mesh(const mesh *m, scaf_error *err)
{
    if (m->nv < 0 || m->nf < 0 || m->nuv < 0 || (m->nv > 0 && !m->V) || (m->nf > 0 && !m->F))
        return err_set(err, SCAF_ERR_MESH, "mesh_write_obj: inconsistent mesh arrays");
    int uv = mesh_has_uv(m);
    if (uv && !m->UV) return err_set(err, SCAF_ERR_MESH, "mesh_write_obj: UV array missing");
    for (size_t k = 0; k < 3 * (size_t)m->nv; k++)
        if (!isfinite(m->V[k]))
            return err_set(err, SCAF_ERR_MESH,
                           "mesh_write_obj: vertex %zu has a non-finite coordinate", k / 3);
    for (size_t k = 0; uv && k < 2 * (size_t)m->nuv; k++)
        if (!isfinite(m->UV[k]))
            return err_set(err, SCAF_ERR_MESH, "mesh_write_obj: UV %zu has a non-finite coordinate",
                           k / 2);
    for (size_t k = 0; k < 3 * (size_t)m->nf; k++) {
        if (m->F[k] < 0 || m->F[k] >= m->nv)
            return err_set(err, SCAF_ERR_MESH, "mesh_write_obj: face %zu uses vertex %d of %d",
                           k / 3, m->F[k], m->nv);
        if (uv && (m->FT[k] < 0 || m->FT[k] >= m->nuv))
            return err_set(err, SCAF_ERR_MESH, "mesh_write_obj: face %zu uses UV %d of %d", k / 3,
                           m->FT[k], m->nuv);
    }
    return SCAF_OK;
}

static int write_body(FILE *f, const mesh *m, const int *group)
{
    char a[40], b[40], c[40];
    int digits = 15; /* what the last number needed (text_scan.h) */
    if (fprintf(f, "# written by scaf %s\n", scaf_version()) < 0) return -1;
    for (int i = 0; i < m->nv; i++) {
        const double *v = m->V + 3 * (size_t)i;
        scan_format_double_hint(a, sizeof a, v[0], &digits);
        scan_format_double_hint(b, sizeof b, v[1], &digits);
        scan_format_double_hint(c, sizeof c, v[2], &digits);
        if (fprintf(f, "v %s %s %s\n", a, b, c) < 0) return -1;
    }
    int uv = mesh_has_uv(m);
    for (int i = 0; uv && i < m->nuv; i++) {
        scan_format_double_hint(a, sizeof a, m->UV[2 * (size_t)i], &digits);
        scan_format_double_hint(b, sizeof b, m->UV[2 * (size_t)i + 1], &digits);
        if (fprintf(f, "vt %s %s\n", a, b) < 0) return -1;
    }
    for (int i = 0; i < m->nf; i++) {
        const int *t = m->F + 3 * (size_t)i;
        int r;
        if (group && (i == 0 || group[i] != group[i - 1]) &&
            fprintf(f, "g chart_%d\n", group[i]) < 0)
            return -1;
        if (uv) {
            const int *u = m->FT + 3 * (size_t)i;
            r = fprintf(f, "f %d/%d %d/%d %d/%d\n", t[0] + 1, u[0] + 1, t[1] + 1, u[1] + 1,
                        t[2] + 1, u[2] + 1);
        } else {
            r = fprintf(f, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
        }
        if (r < 0) return -1;
    }
    return ferror(f) ? -1 : 0;
}

scaf_status mesh_write_obj(const char *path, const mesh *m, scaf_error *err)
{
    return mesh_write_obj_grouped(path, m, NULL, err);
}

scaf_status mesh_write_obj_grouped(const char *path, const mesh *m, const int *face_group,
                                   scaf_error *err)
{
    if (!path || !*path || !m)
        return err_set(err, SCAF_ERR_USAGE, "mesh_write_obj: no path or mesh");
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
    if (write_body(af.f, m, face_group) != 0) {
        atomic_abort(&af);
        free(buf);
        return err_set(err, SCAF_ERR_IO, "%s: cannot write (disk full?)", path);
    }
    st = atomic_commit(&af, err);
    free(buf);
    return st;
}
