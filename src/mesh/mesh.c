/* mesh/mesh: allocation of the mesh arrays (see mesh.h). */
#include "mesh/mesh.h"

#include <stdlib.h>
#include <string.h>

scaf_status mesh_alloc(mesh *m, int nv, int nf, int nuv, scaf_error *err)
{
    memset(m, 0, sizeof *m);
    if (nv < 0 || nf < 0 || nuv < 0)
        return err_set(err, SCAF_ERR_USAGE, "mesh_alloc: negative size");
    m->V = malloc(sizeof(double) * 3 * (size_t)(nv ? nv : 1));
    m->F = malloc(sizeof(int) * 3 * (size_t)(nf ? nf : 1));
    if (nuv > 0) {
        m->UV = malloc(sizeof(double) * 2 * (size_t)nuv);
        m->FT = malloc(sizeof(int) * 3 * (size_t)(nf ? nf : 1));
    }
    if (!m->V || !m->F || (nuv > 0 && (!m->UV || !m->FT))) {
        mesh_free(m);
        return err_nomem(err, "mesh arrays");
    }
    m->nv = nv;
    m->nf = nf;
    m->nuv = nuv;
    return SCAF_OK;
}

void mesh_free(mesh *m)
{
    if (!m) return;
    free(m->V);
    free(m->F);
    free(m->UV);
    free(m->FT);
    memset(m, 0, sizeof *m);
}
