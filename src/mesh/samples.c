/* mesh/samples: procedural sample meshes (see samples.h).
 *
 * Each generator fills a mesh allocated to its exact size; vertices shared
 * between pieces (cube faces, plate cells) are found through an integer
 * lattice index so the surfaces are welded exactly. Fails only on an
 * unknown name, a size out of range, or allocation.
 */
#include "mesh/samples.h"
#include "mesh/dented_sphere.h"
#include "mesh/spiral_strip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static const mesh_sample_info SAMPLES[] = {
    {"triangle", "a single triangle (size ignored)", 1, 1, 1},
    {"grid", "flat n x n square grid with UVs = xy (a disk)", 8, 1, 3000},
    {"hemisphere", "bumpy open hemisphere with n rings, 6n^2 faces (a disk)", 16, 1, 2000},
    {"holes", "curved plate with 6 circular holes, n points per cell side (genus 0, 7 loops)", 8, 2,
     1000},
    {"cubesphere", "closed bumpy sphere, 6 UV charts (cube faces of n x n cells), 12n seam edges",
     8, 1, 256},
    {"tetrahedron", "a closed tetrahedron (size ignored)", 1, 1, 1},
    {"spiral",
     "thin open strip along a circle, n segments (Figure 4 of the SCAF paper; gen also writes "
     "targets)",
     26, 3, 1000},
    {"icosphere",
     "closed unit geodesic sphere, each icosahedron face cut n x n: 20n^2 faces, no UVs", 4, 1,
     200},
    {"dented",
     "closed sphere whose top cap is pushed down through its bottom: intersects itself "
     "(20n^2 faces)",
     6, 2, 200},
};

int mesh_sample_count(void) { return (int)(sizeof SAMPLES / sizeof SAMPLES[0]); }

const mesh_sample_info *mesh_sample_get(int i)
{
    return i >= 0 && i < mesh_sample_count() ? &SAMPLES[i] : NULL;
}

const mesh_sample_info *mesh_sample_find(const char *name)
{
    for (int i = 0; i < mesh_sample_count(); i++)
        if (!strcmp(SAMPLES[i].name, name)) return &SAMPLES[i];
    return NULL;
}

static void set3(int *p, int a, int b, int c)
{
    p[0] = a;
    p[1] = b;
    p[2] = c;
}

/* ---- triangle, tetrahedron ---- */
static scaf_status make_triangle(mesh *m, scaf_error *err)
{
    scaf_status st = mesh_alloc(m, 3, 1, 3, err);
    if (st) return st;
    const double V[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    memcpy(m->V, V, sizeof V);
    for (int i = 0; i < 3; i++) {
        m->UV[2 * i] = V[3 * i];
        m->UV[2 * i + 1] = V[3 * i + 1];
    }
    set3(m->F, 0, 1, 2);
    set3(m->FT, 0, 1, 2);
    return SCAF_OK;
}

static scaf_status make_tetrahedron(mesh *m, scaf_error *err)
{
    scaf_status st = mesh_alloc(m, 4, 4, 0, err);
    if (st) return st;
    const double V[12] = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
    memcpy(m->V, V, sizeof V);
    /* outward: each face seen from outside is counter-clockwise */
    set3(m->F + 0, 0, 1, 2);
    set3(m->F + 3, 0, 3, 1);
    set3(m->F + 6, 0, 2, 3);
    set3(m->F + 9, 1, 3, 2);
    return SCAF_OK;
}

/* ---- grid: (n+1)^2 vertices on [0,1]^2 ---- */
static scaf_status make_grid(int n, mesh *m, scaf_error *err)
{
    int w = n + 1;
    scaf_status st = mesh_alloc(m, w * w, 2 * n * n, w * w, err);
    if (st) return st;
    for (int j = 0; j < w; j++)
        for (int i = 0; i < w; i++) {
            int v = j * w + i;
            m->V[3 * v] = m->UV[2 * v] = (double)i / n;
            m->V[3 * v + 1] = m->UV[2 * v + 1] = (double)j / n;
            m->V[3 * v + 2] = 0;
        }
    int f = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * w + i, b = a + 1, c = a + w + 1, d = a + w;
            set3(m->F + 3 * f++, a, b, c);
            set3(m->F + 3 * f++, a, c, d);
        }
    memcpy(m->FT, m->F, sizeof(int) * 3 * (size_t)m->nf);
    return SCAF_OK;
}

/* ---- hemisphere: hexagonal disk triangulation (ring i has 6i vertices)
 * mapped to the upper unit hemisphere, radius modulated by bumps ---- */
static int ring_start(int i) { return i == 0 ? 0 : 1 + 3 * i * (i - 1); }

static scaf_status make_hemisphere(int n, mesh *m, scaf_error *err)
{
    int nv = 1 + 3 * n * (n + 1), nf = 6 * n * n;
    scaf_status st = mesh_alloc(m, nv, nf, 0, err);
    if (st) return st;
    for (int i = 0; i <= n; i++) {
        int cnt = i == 0 ? 1 : 6 * i;
        for (int k = 0; k < cnt; k++) {
            double rho = (double)i / n, phi = i == 0 ? 0 : 2 * PI * k / cnt;
            double theta = rho * PI / 2;
            double r =
                1 + 0.06 * sin(5 * phi) * sin(2 * theta) + 0.03 * cos(7 * theta) * sin(3 * phi + 1);
            double *p = m->V + 3 * (ring_start(i) + k);
            p[0] = r * sin(theta) * cos(phi);
            p[1] = r * sin(theta) * sin(phi);
            p[2] = r * cos(theta);
        }
    }
    int f = 0;
    for (int i = 1; i <= n; i++) {
        int so = ring_start(i), co = 6 * i, si = ring_start(i - 1), ci = i == 1 ? 1 : 6 * (i - 1);
        for (int s = 0; s < 6; s++)
            for (int j = 0; j < i; j++) {
                int o0 = so + (s * i + j) % co, o1 = so + (s * i + j + 1) % co;
                int in0 = si + (s * (i - 1) + j) % ci;
                set3(m->F + 3 * f++, in0, o0, o1);
                if (j < i - 1) {
                    int in1 = si + (s * (i - 1) + j + 1) % ci;
                    set3(m->F + 3 * f++, in0, o1, in1);
                }
            }
    }
    return SCAF_OK;
}

/* ---- holes: 3 x 2 unit cells, each the ring between the cell's square
 * boundary (4n points, shared with neighbours) and a circle of radius
 * 0.3, with `rings` intermediate loops; lifted onto a curved surface ---- */
#define HOLES_X 3
#define HOLES_Y 2

static scaf_status make_holes(int n, mesh *m, scaf_error *err)
{
    int rings = n / 2 > 1 ? n / 2 : 1; /* loops strictly inside the cell */
    int per = 4 * n;                   /* points per loop */
    int lw = HOLES_X * n + 1, lh = HOLES_Y * n + 1;
    int cells = HOLES_X * HOLES_Y;
    /* lattice points on the cell lines: horizontal + vertical - crossings */
    int nv_lattice = lw * (HOLES_Y + 1) + lh * (HOLES_X + 1) - (HOLES_X + 1) * (HOLES_Y + 1);
    int nv = nv_lattice + cells * per * rings;
    int nf = cells * per * rings * 2;
    int *lat = malloc((size_t)lw * (size_t)lh * sizeof *lat);
    int *loop = malloc((size_t)per * (size_t)(rings + 1) * sizeof *loop);
    if (!lat || !loop) {
        free(lat);
        free(loop);
        return err_nomem(err, "sample holes");
    }
    scaf_status st = mesh_alloc(m, nv, nf, 0, err);
    if (st) {
        free(lat);
        free(loop);
        return st;
    }
    for (int i = 0; i < lw * lh; i++) lat[i] = -1;
    int v = 0, f = 0;
    for (int cy = 0; cy < HOLES_Y; cy++)
        for (int cx = 0; cx < HOLES_X; cx++) {
            /* loop 0: the square boundary, counter-clockwise from the
             * lower-left corner, in lattice units */
            for (int k = 0; k < per; k++) {
                int side = k / n, t = k % n, X, Y;
                switch (side) {
                case 0:
                    X = t;
                    Y = 0;
                    break;
                case 1:
                    X = n;
                    Y = t;
                    break;
                case 2:
                    X = n - t;
                    Y = n;
                    break;
                default:
                    X = 0;
                    Y = n - t;
                    break;
                }
                X += cx * n;
                Y += cy * n;
                int *slot = &lat[Y * lw + X];
                if (*slot < 0) {
                    *slot = v;
                    double *p = m->V + 3 * v++;
                    p[0] = (double)X / n;
                    p[1] = (double)Y / n;
                }
                loop[k] = *slot;
            }
            /* loops 1..rings: between the square and the circle */
            double ox = cx + 0.5, oy = cy + 0.5;
            for (int r = 1; r <= rings; r++) {
                double t = (double)r / rings;
                for (int k = 0; k < per; k++) {
                    const double *q = m->V + 3 * loop[k];
                    double dx = q[0] - ox, dy = q[1] - oy, len = sqrt(dx * dx + dy * dy);
                    double *p = m->V + 3 * v;
                    p[0] = ox + (1 - t) * dx + t * 0.3 * dx / len;
                    p[1] = oy + (1 - t) * dy + t * 0.3 * dy / len;
                    loop[r * per + k] = v++;
                }
            }
            for (int r = 0; r < rings; r++)
                for (int k = 0; k < per; k++) {
                    int k1 = (k + 1) % per;
                    int s0 = loop[r * per + k], s1 = loop[r * per + k1];
                    int c0 = loop[(r + 1) * per + k], c1 = loop[(r + 1) * per + k1];
                    set3(m->F + 3 * f++, s0, s1, c1);
                    set3(m->F + 3 * f++, s0, c1, c0);
                }
        }
    if (v != nv || f != nf) {
        free(lat);
        free(loop);
        mesh_free(m);
        return err_set(err, SCAF_ERR_INTERNAL,
                       "holes: built %d vertices / %d faces, expected %d / %d", v, f, nv, nf);
    }
    for (int i = 0; i < v; i++) {
        double *p = m->V + 3 * i;
        p[2] = 0.25 * sin(1.1 * p[0]) * cos(0.9 * p[1]) + 0.1 * p[0] * p[1];
    }
    free(lat);
    free(loop);
    return SCAF_OK;
}

/* ---- cubesphere: lattice points of the cube [0,n]^3 surface, pushed to a
 * bumpy sphere; each cube face is a chart with its own vt grid ---- */
static scaf_status make_cubesphere(int n, mesh *m, scaf_error *err)
{
    int w = n + 1;
    int nv = 6 * n * n + 2, nf = 12 * n * n, nuv = 6 * w * w;
    size_t nlat = (size_t)w * w * w;
    int *lat = malloc(nlat * sizeof *lat);
    if (!lat) return err_nomem(err, "sample cubesphere");
    scaf_status st = mesh_alloc(m, nv, nf, nuv, err);
    if (st) {
        free(lat);
        return st;
    }
    for (size_t i = 0; i < nlat; i++) lat[i] = -1;
    /* per face: fixed axis and value, then axes u and v with u x v outward */
    static const int FACE[6][4] = {
        {0, 1, 1, 2}, {0, 0, 2, 1}, {1, 1, 2, 0}, {1, 0, 0, 2}, {2, 1, 0, 1}, {2, 0, 1, 0},
    };
    int v = 0, f = 0;
    for (int c = 0; c < 6; c++) {
        int fixed = FACE[c][0], ua = FACE[c][2], va = FACE[c][3];
        int fixed_val = FACE[c][1] ? n : 0;
        for (int b = 0; b < w; b++)
            for (int a = 0; a < w; a++) {
                int q[3];
                q[fixed] = fixed_val;
                q[ua] = a;
                q[va] = b;
                int *slot = &lat[((size_t)q[2] * w + q[1]) * w + q[0]];
                if (*slot < 0) {
                    double x = 2.0 * q[0] / n - 1, y = 2.0 * q[1] / n - 1, z = 2.0 * q[2] / n - 1;
                    double len = sqrt(x * x + y * y + z * z);
                    x /= len, y /= len, z /= len;
                    double r = 1 + 0.08 * sin(4 * x + 1) * sin(4 * y) * cos(3 * z);
                    double *p = m->V + 3 * v;
                    p[0] = r * x;
                    p[1] = r * y;
                    p[2] = r * z;
                    *slot = v++;
                }
                int t = c * w * w + b * w + a;
                /* atlas: chart c in cell (c % 3, c / 3) of a 3 x 2 grid of
                 * squares of side 1/3, with a margin */
                m->UV[2 * t] = ((c % 3) + 0.05 + 0.9 * a / n) / 3.0;
                m->UV[2 * t + 1] = ((c / 3) + 0.05 + 0.9 * b / n) / 3.0;
            }
        for (int b = 0; b < n; b++)
            for (int a = 0; a < n; a++) {
                int t00 = c * w * w + b * w + a, t10 = t00 + 1, t11 = t00 + w + 1, t01 = t00 + w;
                int q00[3], q10[3], q11[3], q01[3];
                q00[fixed] = q10[fixed] = q11[fixed] = q01[fixed] = fixed_val;
                q00[ua] = a, q00[va] = b;
                q10[ua] = a + 1, q10[va] = b;
                q11[ua] = a + 1, q11[va] = b + 1;
                q01[ua] = a, q01[va] = b + 1;
#define LAT(q) lat[((size_t)(q)[2] * w + (q)[1]) * w + (q)[0]]
                set3(m->F + 3 * f, LAT(q00), LAT(q10), LAT(q11));
                set3(m->FT + 3 * f++, t00, t10, t11);
                set3(m->F + 3 * f, LAT(q00), LAT(q11), LAT(q01));
                set3(m->FT + 3 * f++, t00, t11, t01);
#undef LAT
            }
    }
    free(lat);
    if (v != nv || f != nf) {
        mesh_free(m);
        return err_set(err, SCAF_ERR_INTERNAL,
                       "cubesphere: built %d vertices / %d faces, expected %d / %d", v, f, nv, nf);
    }
    return SCAF_OK;
}

/* ---- icosphere: each icosahedron face an n-frequency triangle lattice,
 * projected onto the unit sphere. Shared corners and edge points get one
 * index: corners 0..11, then n - 1 points per edge (numbered from the
 * edge's lower corner), then the face interiors. ---- */
static const int ICO_F[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

/* Global index of lattice point (i, j) of face f (weights n-i-j, i, j on
 * its corners a, b, c); edge[a][b] is the edge number of corners a, b. */
static int ico_point(int n, int f, int i, int j, int edge[12][12])
{
    const int *c = ICO_F[f];
    if (i == 0 && j == 0) return c[0];
    if (i == n) return c[1];
    if (j == n) return c[2];
    int from = -1, to = -1, t = 0;
    if (j == 0) from = c[0], to = c[1], t = i;
    else if (i == 0) from = c[0], to = c[2], t = j;
    else if (i + j == n) from = c[1], to = c[2], t = j;
    if (from >= 0) {
        if (from > to) t = n - t;
        return 12 + edge[from][to] * (n - 1) + t - 1;
    }
    /* interior: rows i = 1..n-2, j = 1..n-1-i */
    int before = 0;
    for (int r = 1; r < i; r++) before += n - 1 - r;
    return 12 + 30 * (n - 1) + f * (n - 1) * (n - 2) / 2 + before + j - 1;
}

static scaf_status make_icosphere(int n, mesh *m, scaf_error *err)
{
    const double g = (1 + sqrt(5.0)) / 2;
    const double C[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                             {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                             {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    int edge[12][12], ne = 0;
    for (int a = 0; a < 12; a++)
        for (int b = 0; b < 12; b++) edge[a][b] = -1;
    for (int f = 0; f < 20; f++)
        for (int k = 0; k < 3; k++) {
            int a = ICO_F[f][k], b = ICO_F[f][(k + 1) % 3];
            if (edge[a][b] < 0) edge[a][b] = edge[b][a] = ne++;
        }
    scaf_status st = mesh_alloc(m, 10 * n * n + 2, 20 * n * n, 0, err);
    if (st) return st;
    int nt = 0;
    for (int f = 0; f < 20; f++) {
        const int *c = ICO_F[f];
        for (int i = 0; i <= n; i++)
            for (int j = 0; i + j <= n; j++) {
                double *p = m->V + 3 * (size_t)ico_point(n, f, i, j, edge), len = 0;
                for (int k = 0; k < 3; k++) {
                    p[k] = (C[c[0]][k] * (n - i - j) + C[c[1]][k] * i + C[c[2]][k] * j) / n;
                    len += p[k] * p[k];
                }
                for (int k = 0; k < 3; k++) p[k] /= sqrt(len);
            }
        for (int i = 0; i < n; i++)
            for (int j = 0; i + j < n; j++) {
                set3(m->F + 3 * (size_t)nt++, ico_point(n, f, i, j, edge),
                     ico_point(n, f, i + 1, j, edge), ico_point(n, f, i, j + 1, edge));
                if (i + j < n - 1)
                    set3(m->F + 3 * (size_t)nt++, ico_point(n, f, i + 1, j, edge),
                         ico_point(n, f, i + 1, j + 1, edge), ico_point(n, f, i, j + 1, edge));
            }
    }
    return SCAF_OK;
}

scaf_status mesh_sample_make(const char *name, int size, mesh *m, scaf_error *err)
{
    memset(m, 0, sizeof *m);
    const mesh_sample_info *info = mesh_sample_find(name ? name : "");
    if (!info) {
        char list[256] = "";
        for (int i = 0; i < mesh_sample_count(); i++) {
            strncat(list, i ? ", " : "", sizeof list - strlen(list) - 1);
            strncat(list, SAMPLES[i].name, sizeof list - strlen(list) - 1);
        }
        return err_set(err, SCAF_ERR_USAGE, "unknown sample '%s' (samples: %s)", name ? name : "",
                       list);
    }
    if (size == 0) size = info->default_size;
    if (size < info->min_size || size > info->max_size)
        return err_set(err, SCAF_ERR_USAGE, "sample '%s': size %d outside [%d, %d]", info->name,
                       size, info->min_size, info->max_size);
    if (!strcmp(info->name, "triangle")) return make_triangle(m, err);
    if (!strcmp(info->name, "tetrahedron")) return make_tetrahedron(m, err);
    if (!strcmp(info->name, "grid")) return make_grid(size, m, err);
    if (!strcmp(info->name, "hemisphere")) return make_hemisphere(size, m, err);
    if (!strcmp(info->name, "holes")) return make_holes(size, m, err);
    if (!strcmp(info->name, "cubesphere")) return make_cubesphere(size, m, err);
    if (!strcmp(info->name, "spiral")) return spiral_strip_make(size, m, err);
    if (!strcmp(info->name, "icosphere")) return make_icosphere(size, m, err);
    if (!strcmp(info->name, "dented")) {
        scaf_status st = make_icosphere(size, m, err);
        if (st == SCAF_OK) dented_sphere_push(m);
        return st;
    }
    return err_set(err, SCAF_ERR_INTERNAL, "sample '%s' has no generator", info->name);
}
