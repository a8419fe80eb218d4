/* examples/atlas_example: a texture atlas through the public C API only.
 *
 *     atlas_example [IN.obj [OUT.obj]]
 *
 * Without arguments it builds its own mesh (five bumpy grid patches of
 * different sizes, five charts); with IN.obj it reads a triangle OBJ (v,
 * vt, f with 1-based indices; the vt seams define the charts when every
 * face has vt). It runs scaf_atlas_* with a progress line per iteration,
 * checks what the library promises (UVs in the unit square, every two
 * charts at least the padding apart as reported), prints the packing
 * efficiency, the smallest chart gap and the per-chart distortion, and
 * writes OUT.obj (v, vt, f v/vt) when given. Exit status 0 on success.
 *
 * Build against an installed scaf:
 *     cc atlas_example.c $(pkg-config --cflags --libs scaf) -lm -o atlas_example
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <scaf/scaf.h>

typedef struct mesh_arrays {
    int nv, nf, nuv;
    double *V, *UV;
    int *F, *FT;
} mesh_arrays;

/* Five curved (r x r)-cell patches, far apart in 3D. */
static int make_patches(mesh_arrays *m, int r)
{
    int np = 5, nvp = (r + 1) * (r + 1), nfp = 2 * r * r;
    memset(m, 0, sizeof *m);
    m->nv = np * nvp;
    m->nf = np * nfp;
    m->V = malloc(sizeof(double) * 3 * (size_t)m->nv);
    m->F = malloc(sizeof(int) * 3 * (size_t)m->nf);
    if (!m->V || !m->F) return -1;
    int f = 0;
    for (int p = 0; p < np; p++) {
        double s = 0.6 + 0.35 * p;
        for (int j = 0; j <= r; j++)
            for (int i = 0; i <= r; i++) {
                double *v = m->V + 3 * (p * nvp + j * (r + 1) + i), x = s * i / r, y = s * j / r;
                v[0] = x + 10.0 * p;
                v[1] = y;
                v[2] = 0.3 * s * sin(1.7 * x / s + p) * cos(1.1 * y / s);
            }
        for (int j = 0; j < r; j++)
            for (int i = 0; i < r; i++) {
                int a = p * nvp + j * (r + 1) + i, b = a + 1, c = a + r + 1, d = c + 1;
                int *t = m->F + 3 * f;
                t[0] = a, t[1] = b, t[2] = d, t[3] = a, t[4] = d, t[5] = c;
                f += 2;
            }
    }
    return 0;
}

static int grow(void **p, int *cap, int need, size_t size)
{
    if (need <= *cap) return 0;
    int c = *cap ? 2 * *cap : 1024;
    while (c < need) c *= 2;
    void *q = realloc(*p, size * (size_t)c);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

/* A small OBJ reader: v, vt, and triangular f lines (v, v/vt, v/vt/vn,
 * v//vn). Returns 0, or -1 with a message on stderr. */
static int read_obj(const char *path, mesh_arrays *m)
{
    memset(m, 0, sizeof *m);
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "atlas_example: cannot open %s\n", path);
        return -1;
    }
    int cv = 0, cf = 0, cft = 0, cuv = 0, faces_with_vt = 0, line = 0, rc = 0;
    char buf[4096];
    while (rc == 0 && fgets(buf, sizeof buf, fp)) {
        line++;
        if (buf[0] == 'v' && buf[1] == ' ') {
            if (grow((void **)&m->V, &cv, m->nv + 1, 3 * sizeof(double))) rc = -1;
            else if (sscanf(buf + 2, "%lf %lf %lf", &m->V[3 * m->nv], &m->V[3 * m->nv + 1],
                            &m->V[3 * m->nv + 2]) != 3)
                rc = -2;
            else m->nv++;
        } else if (buf[0] == 'v' && buf[1] == 't' && buf[2] == ' ') {
            if (grow((void **)&m->UV, &cuv, m->nuv + 1, 2 * sizeof(double))) rc = -1;
            else if (sscanf(buf + 3, "%lf %lf", &m->UV[2 * m->nuv], &m->UV[2 * m->nuv + 1]) != 2)
                rc = -2;
            else m->nuv++;
        } else if (buf[0] == 'f' && buf[1] == ' ') {
            if (grow((void **)&m->F, &cf, m->nf + 1, 3 * sizeof(int)) ||
                grow((void **)&m->FT, &cft, m->nf + 1, 3 * sizeof(int))) {
                rc = -1;
                break;
            }
            char *s = buf + 2;
            int k = 0, has_vt = 1;
            for (; k < 4; k++) {
                char *end;
                long v = strtol(s, &end, 10);
                if (end == s) break;
                if (k == 3 || v < 1) {
                    rc = -2; /* not a triangle, or a relative index */
                    break;
                }
                long t = 0;
                if (*end == '/' && end[1] != '/') t = strtol(end + 1, &end, 10);
                if (t < 1) has_vt = 0;
                while (*end && *end != ' ' && *end != '\t') end++;
                m->F[3 * m->nf + k] = (int)v - 1;
                m->FT[3 * m->nf + k] = (int)t - 1;
                s = end;
            }
            if (rc == 0 && k != 3) rc = -2;
            if (rc == 0) {
                faces_with_vt += has_vt;
                m->nf++;
            }
        }
    }
    fclose(fp);
    if (rc == -1) fprintf(stderr, "atlas_example: out of memory reading %s\n", path);
    if (rc == -2)
        fprintf(stderr, "atlas_example: %s:%d: unsupported line (only v, vt, triangles)\n", path,
                line);
    if (rc == 0 && faces_with_vt != m->nf) m->nuv = 0; /* charts = components */
    return rc;
}

static int write_obj(const char *path, const mesh_arrays *m, const double *UV, int nuv,
                     const int *FT)
{
    FILE *fp = fopen(path, "w");
    if (!fp) return -1;
    for (int i = 0; i < m->nv; i++)
        fprintf(fp, "v %.17g %.17g %.17g\n", m->V[3 * i], m->V[3 * i + 1], m->V[3 * i + 2]);
    for (int i = 0; i < nuv; i++) fprintf(fp, "vt %.17g %.17g\n", UV[2 * i], UV[2 * i + 1]);
    for (int f = 0; f < m->nf; f++)
        fprintf(fp, "f %d/%d %d/%d %d/%d\n", m->F[3 * f] + 1, FT[3 * f] + 1, m->F[3 * f + 1] + 1,
                FT[3 * f + 1] + 1, m->F[3 * f + 2] + 1, FT[3 * f + 2] + 1);
    return fclose(fp) == 0 ? 0 : -1;
}

static int on_progress(const scaf_atlas_iteration_info_t *it, void *user)
{
    (void)user;
    printf("  %-7s %3d  E %.5f  efficiency %.3f  gap %.5f\n",
           it->phase == SCAF_ATLAS_SETTLE ? "settle" : "compact", it->phase_iteration, it->energy,
           it->efficiency, it->gap);
    return 0; /* nonzero would stop the run (SCAF_ERR_CANCELLED) */
}

int main(int argc, char **argv)
{
    mesh_arrays m;
    if (argc > 1 ? read_obj(argv[1], &m) : make_patches(&m, 6)) return 1;
    printf("scaf %s: %d vertices, %d triangles%s\n", scaf_version(), m.nv, m.nf,
           m.nuv ? ", charts from vt" : "");

    scaf_atlas_options_t opt = scaf_atlas_options_default();
    opt.padding = 4.0 / 1024.0; /* 4 texels of a 1024 x 1024 texture */
    opt.settle_iterations = 10;
    opt.compact_iterations = 20;
    scaf_atlas_t *a = scaf_atlas_new(&opt);
    if (!a) { /* out of memory, or an option out of range: the check says which */
        char why[256] = "out of memory";
        scaf_atlas_options_check(&opt, why, sizeof why);
        fprintf(stderr, "%s\n", why);
        return 1;
    }
    int rc = 1;
    double *UV = NULL, *E = NULL;
    int *FT = NULL;
    scaf_status st = scaf_atlas_set_mesh(a, m.V, m.nv, m.F, m.nf, m.nuv ? m.UV : NULL, m.nuv,
                                         m.nuv ? m.FT : NULL);
    if (st == SCAF_OK) st = scaf_atlas_run(a, on_progress, NULL);
    if (st != SCAF_OK) {
        fprintf(stderr, "atlas_example: %s: %s\n", scaf_status_name(st), scaf_atlas_error(a));
        goto done;
    }
    int nuv = scaf_atlas_uv_count(a), nc = scaf_atlas_chart_count(a);
    UV = malloc(sizeof(double) * 2 * (size_t)nuv);
    FT = malloc(sizeof(int) * 3 * (size_t)m.nf);
    E = malloc(sizeof(double) * (size_t)nc);
    if (!UV || !FT || !E) goto done;
    if (scaf_atlas_get_uv(a, UV, FT, NULL) != SCAF_OK ||
        scaf_atlas_chart_distortion(a, E) != SCAF_OK) {
        fprintf(stderr, "atlas_example: %s\n", scaf_atlas_error(a));
        goto done;
    }
    /* what the library promises, seen from outside */
    for (int i = 0; i < 2 * nuv; i++)
        if (!(UV[i] >= 0.0 && UV[i] <= 1.0)) {
            fprintf(stderr, "atlas_example: UV %d outside the unit square\n", i / 2);
            goto done;
        }
    double gap = scaf_atlas_min_chart_gap(a), eff = scaf_atlas_packing_efficiency(a), worst = 0.0;
    if (nc > 1 && !(gap >= opt.padding)) {
        fprintf(stderr, "atlas_example: chart gap %g below the padding %g\n", gap, opt.padding);
        goto done;
    }
    for (int c = 0; c < nc; c++) worst = fmax(worst, E[c]);
    printf("atlas: %d charts, %d UVs, packing efficiency %.3f, min chart gap %.5f (padding %.5f), "
           "E %.4f (worst chart %.4f)\n",
           nc, nuv, eff, gap, opt.padding, scaf_atlas_energy(a), worst);
    if (argc > 2 && write_obj(argv[2], &m, UV, nuv, FT) != 0) {
        fprintf(stderr, "atlas_example: cannot write %s\n", argv[2]);
        goto done;
    }
    rc = 0;
done:
    scaf_atlas_destroy(a);
    free(UV);
    free(FT);
    free(E);
    free(m.V);
    free(m.F);
    free(m.UV);
    free(m.FT);
    return rc;
}
