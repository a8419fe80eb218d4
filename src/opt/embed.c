/* opt/embed: initial bijective map of one chart into the plane.
 *
 * Steps: validate, fill holes with fans, pin the outer loop to the circle,
 * assemble the weighted Laplacian of the free vertices (boundary columns
 * moved to the right side), solve for u and v together, drop the fill,
 * check every original triangle exactly, and on a flip or a failed solve
 * try the next method of the chain (harmonic -> mean-value -> Tutte; the
 * mean-value system is assembled and solved in opt/mvc because it is not
 * symmetric). Loop direction is read from the
 * faces: the face that owns boundary edge a -> b says which way is
 * counter-clockwise.
 */
#include "opt/embed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "geom/predicates.h"
#include "opt/cholmod_solver.h"
#include "opt/cotan_laplacian.h"
#include "opt/csc.h"
#include "opt/energy.h"
#include "opt/mvc.h"
#include "opt/simplices.h"

static const double SCAF_PI = 3.14159265358979323846;

/* Number of faces with edge {a, b} among the half-edges he (n of them,
 * sorted by base/half_edges); *a_to_b gets whether (one of) them walks
 * a -> b. */
static int edge_uses(const int *he, int n, const int *F, int a, int b, int *a_to_b)
{
    int lo = a < b ? a : b, hi = a < b ? b : a;
    int l = 0, r = n;
    while (l < r) {
        int m = l + (r - l) / 2, mlo = half_edge_lo(F, he[m]), mhi = half_edge_hi(F, he[m]);
        if (mlo < lo || (mlo == lo && mhi < hi)) l = m + 1;
        else r = m;
    }
    int cnt = 0;
    for (int k = l; k < n && half_edge_lo(F, he[k]) == lo && half_edge_hi(F, he[k]) == hi; k++) {
        cnt++;
        *a_to_b = F[he[k]] == a;
    }
    return cnt;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Solve the Laplace system on the filled disk. UV2 holds boundary values
 * on entry (fixed[v] != 0) and all values on success. */
static scaf_status solve_laplace(int nv2, const double *V2, int nf2, const int *F2,
                                 const unsigned char *fixed, int cotan, double *UV2,
                                 scaf_error *err)
{
    int *dof = malloc((size_t)nv2 * sizeof *dof);
    size_t cap = (size_t)nf2 * 12 + 1;
    int *I = malloc(cap * sizeof *I), *Jc = malloc(cap * sizeof *Jc);
    double *Val = malloc(cap * sizeof *Val);
    double *b = NULL, *x = NULL;
    opt_csc A = {0};
    opt_chol *ch = NULL;
    scaf_status st = SCAF_OK;
    if (!dof || !I || !Jc || !Val) {
        st = err_nomem(err, "embedding system");
        goto done;
    }
    int n = 0;
    for (int v = 0; v < nv2; v++) dof[v] = fixed[v] ? -1 : n++;
    b = calloc(2 * (size_t)(n ? n : 1), sizeof *b);
    x = malloc(2 * (size_t)(n ? n : 1) * sizeof *x);
    if (!b || !x) {
        st = err_nomem(err, "embedding system");
        goto done;
    }
    int nt = 0;
    for (int f = 0; f < nf2; f++) {
        for (int k = 0; k < 3; k++) {
            int o = F2[3 * f + k], i = F2[3 * f + (k + 1) % 3], j = F2[3 * f + (k + 2) % 3];
            double w = cotan
                ? 0.5 * opt_cot_at(V2 + 3 * (size_t)o, V2 + 3 * (size_t)i, V2 + 3 * (size_t)j)
                : 1.0;
            if (!isfinite(w)) {
                st = err_set(err, SCAF_ERR_NUMERIC,
                             "embedding: face %d has a non-finite cotangent weight", f);
                goto done;
            }
            int di = dof[i], dj = dof[j];
            if (di >= 0) {
                I[nt] = di;
                Jc[nt] = di;
                Val[nt++] = w;
            }
            if (dj >= 0) {
                I[nt] = dj;
                Jc[nt] = dj;
                Val[nt++] = w;
            }
            if (di >= 0 && dj >= 0) {
                I[nt] = di;
                Jc[nt] = dj;
                Val[nt++] = -w;
            } else if (di >= 0) {
                b[di] += w * UV2[2 * (size_t)j];
                b[n + di] += w * UV2[2 * (size_t)j + 1];
            } else if (dj >= 0) {
                b[dj] += w * UV2[2 * (size_t)i];
                b[n + dj] += w * UV2[2 * (size_t)i + 1];
            }
        }
    }
    if (n > 0) {
        st = opt_csc_from_triplets(&A, n, nt, I, Jc, Val, err);
        if (st != SCAF_OK) goto done;
        /* CHOLMOD's default tries AMD and switches to METIS when the fill
         * is high (large charts), which pays off for a one-off solve. */
        ch = opt_chol_create(OPT_ORDER_CHOLMOD_DEFAULT, err);
        if (!ch) {
            st = err->code;
            goto done;
        }
        st = opt_chol_factor(ch, &A, err);
        if (st != SCAF_OK) goto done;
        st = opt_chol_solve(ch, 2, b, x, err);
        if (st != SCAF_OK) goto done;
        for (int v = 0; v < nv2; v++)
            if (dof[v] >= 0) {
                UV2[2 * (size_t)v] = x[dof[v]];
                UV2[2 * (size_t)v + 1] = x[n + dof[v]];
            }
    }
done:
    opt_chol_destroy(ch);
    opt_csc_free(&A);
    free(dof);
    free(I);
    free(Jc);
    free(Val);
    free(b);
    free(x);
    return st;
}

scaf_status opt_embed_chart(int nv, const double *V, int nf, const int *F,
                            const opt_chart_loops *loops, opt_embed_method method, double *UV,
                            int *used_fallback, scaf_error *err)
{
    scaf_error tmp;
    if (!err) err = &tmp;
    if (used_fallback) *used_fallback = 0;
    /* ---- check inputs ---- */
    if (nv < 3 || nf < 1)
        return err_set(err, SCAF_ERR_MESH, "chart has %d vertices and %d faces", nv, nf);
    if (!loops || loops->nloops < 1)
        return err_set(err, SCAF_ERR_MESH, "chart has no boundary loop (closed surface?)");
    for (int k = 0; k < 3 * nf; k++)
        if (F[k] < 0 || F[k] >= nv)
            return err_set(err, SCAF_ERR_USAGE, "face %d references vertex %d but the chart has %d",
                           k / 3, F[k], nv);
    int nl = loops->nloops;
    for (int l = 0; l < nl; l++)
        if (loops->start[l + 1] - loops->start[l] < 3)
            return err_set(err, SCAF_ERR_MESH,
                           "boundary loop %d has %d vertices (at least 3 needed)", l,
                           loops->start[l + 1] - loops->start[l]);
    unsigned char *onloop = calloc((size_t)nv, 1);
    if (!onloop) return err_nomem(err, "embedding");
    for (int l = 0; l < nl; l++)
        for (int k = loops->start[l]; k < loops->start[l + 1]; k++) {
            int v = loops->vertices[k];
            if (v < 0 || v >= nv) {
                free(onloop);
                return err_set(err, SCAF_ERR_USAGE,
                               "boundary loop %d references vertex %d but the chart has %d", l, v,
                               nv);
            }
            if (onloop[v]) {
                free(onloop);
                return err_set(err, SCAF_ERR_MESH,
                               "vertex %d appears twice on the boundary loops (non-manifold "
                               "boundary)",
                               v);
            }
            onloop[v] = 1;
        }
    free(onloop);
    double area = 0;
    for (int f = 0; f < nf; f++)
        area += opt_tri_area3(V + 3 * (size_t)F[3 * f], V + 3 * (size_t)F[3 * f + 1],
                              V + 3 * (size_t)F[3 * f + 2]);
    if (!(area > 0) || !isfinite(area))
        return err_set(err, SCAF_ERR_MESH, "chart has 3D area %g", area);
    /* Loop lengths, outer choice, directions (every loop edge must be a
     * boundary edge, walked the same way by the loop). */
    int nhe = 0;
    int *he = malloc(3 * (size_t)nf * sizeof *he);
    int *dir = malloc((size_t)nl * sizeof *dir);
    if (!he || !dir || half_edges_sort(nv, nf, F, NULL, he, &nhe, err) != SCAF_OK) {
        free(he);
        free(dir);
        return err_nomem(err, "embedding");
    }
    int outer = loops->outer;
    double best = -1;
    for (int l = 0; l < nl; l++) {
        const int *lv = loops->vertices + loops->start[l];
        int len = loops->start[l + 1] - loops->start[l];
        double L = 0;
        for (int k = 0; k < len; k++) {
            int a = lv[k], b = lv[(k + 1) % len], fwd = 0;
            int uses = edge_uses(he, nhe, F, a, b, &fwd);
            if (uses != 1 || (k > 0 && fwd != dir[l])) {
                free(he);
                free(dir);
                return err_set(err, SCAF_ERR_MESH, "boundary loop %d: edge %d-%d is %s", l, a, b,
                               uses == 0      ? "not an edge of any face"
                                   : uses > 1 ? "shared by several faces (not a boundary edge)"
                                              : "walked against the loop's direction");
            }
            dir[l] = fwd;
            L += dist3(V + 3 * (size_t)a, V + 3 * (size_t)b);
        }
        if (loops->outer < 0 && L > best) {
            best = L;
            outer = l;
        }
    }
    free(he);
    if (outer < 0 || outer >= nl) {
        free(dir);
        return err_set(err, SCAF_ERR_USAGE, "outer loop %d of %d", outer, nl);
    }
    /* ---- filled disk ---- */
    int nholes = nl - 1, nfill = 0;
    for (int l = 0; l < nl; l++)
        if (l != outer) nfill += loops->start[l + 1] - loops->start[l];
    int nv2 = nv + nholes, nf2 = nf + nfill;
    double *V2 = malloc(3 * (size_t)nv2 * sizeof *V2);
    int *F2 = malloc(3 * (size_t)nf2 * sizeof *F2);
    double *UV2 = calloc(2 * (size_t)nv2, sizeof *UV2);
    unsigned char *fixed = calloc((size_t)nv2, 1);
    unsigned char *used = calloc((size_t)nv2, 1);
    scaf_status st = SCAF_OK;
    if (!V2 || !F2 || !UV2 || !fixed || !used) {
        st = err_nomem(err, "embedding");
        goto done;
    }
    memcpy(V2, V, 3 * (size_t)nv * sizeof *V2);
    memcpy(F2, F, 3 * (size_t)nf * sizeof *F2);
    int fv = nv, ff = nf;
    for (int l = 0; l < nl; l++) {
        if (l == outer) continue;
        const int *lv = loops->vertices + loops->start[l];
        int len = loops->start[l + 1] - loops->start[l];
        double c[3] = {0, 0, 0};
        for (int k = 0; k < len; k++)
            for (int r = 0; r < 3; r++) c[r] += V[3 * (size_t)lv[k] + r] / len;
        memcpy(V2 + 3 * (size_t)fv, c, sizeof c);
        for (int k = 0; k < len; k++) {
            int a = lv[k], b = lv[(k + 1) % len];
            /* The chart's face has a -> b (dir 1) or b -> a: the fan takes the other side. */
            F2[3 * ff] = dir[l] ? b : a;
            F2[3 * ff + 1] = dir[l] ? a : b;
            F2[3 * ff + 2] = fv;
            ff++;
        }
        fv++;
    }
    for (int k = 0; k < 3 * nf2; k++) used[F2[k]] = 1;
    /* ---- outer loop on the circle ---- */
    {
        const int *lv = loops->vertices + loops->start[outer];
        int len = loops->start[outer + 1] - loops->start[outer];
        double L = 0;
        for (int k = 0; k < len; k++)
            L += dist3(V + 3 * (size_t)lv[k], V + 3 * (size_t)lv[(k + 1) % len]);
        double r = sqrt(area / SCAF_PI), s = 0;
        for (int k = 0; k < len; k++) {
            /* Counter-clockwise along the faces' orientation. */
            int v = dir[outer] ? lv[k] : lv[(len - k) % len];
            int w = dir[outer] ? lv[(k + 1) % len] : lv[(2 * len - k - 1) % len];
            double ang = 2.0 * SCAF_PI * s / L;
            UV2[2 * (size_t)v] = r * cos(ang);
            UV2[2 * (size_t)v + 1] = r * sin(ang);
            fixed[v] = 1;
            s += dist3(V + 3 * (size_t)v, V + 3 * (size_t)w);
        }
    }
    for (int v = 0; v < nv2; v++)
        if (!used[v]) fixed[v] = 1; /* unreferenced: stays at the center */
    /* ---- solve, check, fall back ---- */
    /* Chain of attempts: the requested method, then Tutte (always valid for
     * a disk). Harmonic tries mean-value before Tutte: its weights are
     * positive, so it is bijective whenever the solve is exact enough. */
    opt_embed_method chain[3];
    int nchain = 0;
    chain[nchain++] = method;
    if (method == OPT_EMBED_HARMONIC) chain[nchain++] = OPT_EMBED_MVC;
    if (method != OPT_EMBED_TUTTE) chain[nchain++] = OPT_EMBED_TUTTE;
    for (int attempt = 0; attempt < nchain; attempt++) {
        opt_embed_method m = chain[attempt];
        scaf_error e2;
        err_clear(&e2);
        if (m == OPT_EMBED_MVC) st = opt_mvc_solve(nv2, V2, nf2, F2, fixed, UV2, &e2);
        else st = solve_laplace(nv2, V2, nf2, F2, fixed, m == OPT_EMBED_HARMONIC, UV2, &e2);
        int bad = -1;
        if (st == SCAF_OK)
            for (int f = 0; f < nf && bad < 0; f++)
                if (!(orient2d(UV2 + 2 * (size_t)F[3 * f], UV2 + 2 * (size_t)F[3 * f + 1],
                               UV2 + 2 * (size_t)F[3 * f + 2]) > 0))
                    bad = f;
        if (st == SCAF_OK && bad < 0) break;
        if (attempt + 1 < nchain && st != SCAF_ERR_NOMEM) {
            if (used_fallback) *used_fallback = 1;
            st = SCAF_OK;
            continue;
        }
        if (st == SCAF_OK)
            st = err_set(err, SCAF_ERR_NUMERIC,
                         "Tutte embedding: triangle %d is inverted or degenerate (is the chart a "
                         "valid disk?)",
                         bad);
        else *err = e2;
        break;
    }
    if (st == SCAF_OK) memcpy(UV, UV2, 2 * (size_t)nv * sizeof *UV);
done:
    free(dir);
    free(V2);
    free(F2);
    free(UV2);
    free(fixed);
    free(used);
    return st;
}

/* The reported energy E of a start: symmetric Dirichlet, area-weighted
 * mean (opt/energy over the chart's 3D rest frames). */
static double start_energy(const opt_simplices *S, const double *UV)
{
    opt_term t = {S, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    return opt_term_mean_energy(&t, UV);
}

typedef struct loop_rank {
    double length;
    int loop;
} loop_rank;

static int cmp_loop_rank(const void *x, const void *y)
{
    const loop_rank *a = x, *b = y;
    if (a->length != b->length) return a->length > b->length ? -1 : 1;
    return a->loop - b->loop;
}

scaf_status opt_embed_chart_best(int nv, const double *V, int nf, const int *F,
                                 const opt_chart_loops *loops, opt_embed_method method,
                                 int max_tries, double *UV, int *used_fallback, double *energy,
                                 scaf_error *err)
{
    scaf_error tmp;
    if (!err) err = &tmp;
    int nl = loops ? loops->nloops : 0;
    /* the rest frames; a chart with a degenerate 3D triangle has no
     * energy to compare starts by, and gets the longest loop */
    opt_simplices S = {0};
    scaf_error serr;
    int measurable = nf > 0 && opt_simplices_from_surface(&S, nv, V, nf, F, &serr) == SCAF_OK;
    if (nl <= 1 || max_tries <= 1 || !measurable) {
        scaf_status st = opt_embed_chart(nv, V, nf, F, loops, method, UV, used_fallback, err);
        if (energy) *energy = st == SCAF_OK && measurable ? start_energy(&S, UV) : NAN;
        opt_simplices_free(&S);
        return st;
    }
    /* candidates: the longest loops first (the longest is the default
     * choice, so it wins ties) */
    loop_rank *rank = malloc(sizeof *rank * (size_t)nl);
    double *trial = malloc(sizeof(double) * 2 * (size_t)nv);
    if (!rank || !trial) {
        free(rank);
        free(trial);
        opt_simplices_free(&S);
        return err_nomem(err, "embedding");
    }
    for (int l = 0; l < nl; l++) {
        const int *lv = loops->vertices + loops->start[l];
        int len = loops->start[l + 1] - loops->start[l];
        double L = 0.0;
        for (int k = 0; k < len && len > 0; k++)
            L += dist3(V + 3 * (size_t)lv[k], V + 3 * (size_t)lv[(k + 1) % len]);
        rank[l].length = L;
        rank[l].loop = l;
    }
    qsort(rank, (size_t)nl, sizeof *rank, cmp_loop_rank);
    int tries = nl < max_tries ? nl : max_tries;
    double best = INFINITY;
    int found = 0, fb = 0;
    scaf_status st = SCAF_OK;
    for (int i = 0; i < tries; i++) {
        opt_chart_loops ol = *loops;
        ol.outer = rank[i].loop;
        int f = 0;
        st = opt_embed_chart(nv, V, nf, F, &ol, method, trial, &f, err);
        if (st == SCAF_ERR_NOMEM || (st != SCAF_OK && !found && i == tries - 1)) break;
        if (st != SCAF_OK) continue; /* another outer loop may still work */
        double e = start_energy(&S, trial);
        if (!found || e < best) {
            best = e;
            fb = f;
            memcpy(UV, trial, sizeof(double) * 2 * (size_t)nv);
        }
        found = 1;
    }
    if (found) {
        st = SCAF_OK;
        err_clear(err);
        if (used_fallback) *used_fallback = fb;
        if (energy) *energy = best;
    }
    free(rank);
    free(trial);
    opt_simplices_free(&S);
    return st;
}
