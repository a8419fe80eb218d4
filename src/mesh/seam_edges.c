/* mesh/seam_edges: the seams of a UV topology (see the header). */
#include "mesh/seam_edges.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"

void seam_edges_free(seam_edges *s)
{
    if (!s) return;
    free(s->ab);
    memset(s, 0, sizeof *s);
}

static double dist3(const double *a, const double *b)
{
    double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

static double tri_area(const double *a, const double *b, const double *c)
{
    double u[3], v[3];
    for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
    double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
           z = u[0] * v[1] - u[1] * v[0];
    return 0.5 * sqrt(x * x + y * y + z * z);
}

/* The UV index at vertex v of face f (-1 if f does not use v). */
static int uv_at(const int *F, const int *FT, int f, int v)
{
    for (int j = 0; j < 3; j++)
        if (F[3 * f + j] == v) return FT[3 * f + j];
    return -1;
}

scaf_status seam_edges_find(int nv, const double *V, int nf, const int *F, const int *FT,
                            seam_edges *s, scaf_error *err)
{
    memset(s, 0, sizeof *s);
    if (nv < 0 || nf < 0 || (nf > 0 && (!V || !F || !FT)))
        return err_set(err, SCAF_ERR_USAGE, "seam_edges: bad arguments");
    int *order = malloc(sizeof(int) * 3 * (size_t)(nf ? nf : 1));
    if (!order) return err_nomem(err, "seam edges");
    int count = 0;
    scaf_status st = half_edges_sort(nv, nf, F, NULL, order, &count, err);
    if (st != SCAF_OK) {
        free(order);
        return st;
    }
    int cap = 0;
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(F, order[i], order[j])) j++;
        int a = half_edge_lo(F, order[i]), b = half_edge_hi(F, order[i]);
        if (j - i == 2 && a != b) {
            int f = order[i] / 3, g = order[i + 1] / 3;
            if (uv_at(F, FT, f, a) != uv_at(F, FT, g, a) ||
                uv_at(F, FT, f, b) != uv_at(F, FT, g, b)) {
                if (s->n == cap) {
                    cap = cap ? 2 * cap : 256;
                    int *ab = realloc(s->ab, sizeof(int) * 2 * (size_t)cap);
                    if (!ab) {
                        free(order);
                        seam_edges_free(s);
                        return err_nomem(err, "seam edges");
                    }
                    s->ab = ab;
                }
                s->ab[2 * s->n] = a;
                s->ab[2 * s->n + 1] = b;
                s->n++;
                s->length += dist3(V + 3 * (size_t)a, V + 3 * (size_t)b);
            }
        }
        i = j;
    }
    free(order);
    for (int f = 0; f < nf; f++)
        s->area += tri_area(V + 3 * (size_t)F[3 * f], V + 3 * (size_t)F[3 * f + 1],
                            V + 3 * (size_t)F[3 * f + 2]);
    s->normalized = s->area > 0.0 ? s->length / sqrt(s->area) : 0.0;
    return SCAF_OK;
}
