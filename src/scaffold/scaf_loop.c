/* scaffold/scaf_loop: the SCAF iteration (see scaf_loop.h).
 *
 * Sections: setup (rest frames, boundary edges), energies, one iteration
 * (scaffold, assembly of the SLIM proxy, CHOLMOD solve, line search).
 * The unknowns are the UV positions of all mesh vertices and of the
 * scaffold vertices not on the box, interleaved (u, v) per vertex; box
 * vertices are fixed and moved to the right-hand side.
 */
#include "scaffold/scaf_loop.h"

#include <cholmod.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geom/predicates.h"
#include "scaffold/tri2.h"

static double now_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- setup ------------------------------------------------------------- */

typedef struct half_edge {
    int lo, hi;   /* sorted endpoints */
    int a, b;     /* as in the face */
} half_edge;

static int cmp_half_edge(const void *x, const void *y)
{
    const half_edge *p = x, *q = y;
    if (p->lo != q->lo) return p->lo < q->lo ? -1 : 1;
    if (p->hi != q->hi) return p->hi < q->hi ? -1 : 1;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    return 0;
}

/* Edges used by exactly one face, oriented as in that face (chart on the
 * left). Chart topology was validated by the caller. */
static scaf_status boundary_edges(int nf, const int *F, int **out, int *nout, scaf_error *err)
{
    size_t nh = 3 * (size_t)nf;
    half_edge *h = malloc(sizeof *h * (nh ? nh : 1));
    int *e = malloc(sizeof(int) * 2 * (nh ? nh : 1));
    if (!h || !e) {
        free(h);
        free(e);
        return err_nomem(err, "boundary edges");
    }
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            int a = F[3 * f + j], b = F[3 * f + (j + 1) % 3];
            half_edge *x = &h[3 * (size_t)f + j];
            x->a = a;
            x->b = b;
            x->lo = a < b ? a : b;
            x->hi = a < b ? b : a;
        }
    qsort(h, nh, sizeof *h, cmp_half_edge);
    int n = 0;
    for (size_t i = 0; i < nh;) {
        size_t j = i + 1;
        while (j < nh && h[j].lo == h[i].lo && h[j].hi == h[i].hi) j++;
        if (j - i == 1) {
            e[2 * n] = h[i].a;
            e[2 * n + 1] = h[i].b;
            n++;
        }
        i = j;
    }
    free(h);
    *out = e;
    *nout = n;
    return SCAF_OK;
}

void scaf_loop_free(scaf_loop *L)
{
    if (!L) return;
    free(L->F);
    free(L->uv);
    free(L->Dminv);
    free(L->area);
    free(L->bedges);
    scaffold_free(&L->sc);
    if (L->chol) {
        cholmod_finish((cholmod_common *)L->chol);
        free(L->chol);
    }
    memset(L, 0, sizeof *L);
}

scaf_status scaf_loop_init(scaf_loop *L, int nv, const double *V3, int nf, const int *F,
                           const double *uv0, const scaf_options_t *opt, scaf_error *err)
{
    memset(L, 0, sizeof *L);
    L->nv = nv;
    L->nf = nf;
    L->opt = opt ? *opt : scaf_options_default();
    L->F = malloc(sizeof(int) * 3 * (size_t)(nf ? nf : 1));
    L->uv = malloc(sizeof(double) * 2 * (size_t)(nv ? nv : 1));
    L->Dminv = malloc(sizeof(double) * 4 * (size_t)(nf ? nf : 1));
    L->area = malloc(sizeof(double) * (size_t)(nf ? nf : 1));
    L->chol = malloc(sizeof(cholmod_common));
    if (!L->F || !L->uv || !L->Dminv || !L->area || !L->chol) {
        free(L->chol);
        L->chol = NULL;
        scaf_loop_free(L);
        return err_nomem(err, "SCAF loop");
    }
    cholmod_common *c = L->chol;
    cholmod_start(c);
    c->print = 0;
    c->supernodal = CHOLMOD_SUPERNODAL;
    /* The scaffold changes the pattern every iteration: one cheap ordering. */
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_AMD;
    c->postorder = 1;
    memcpy(L->F, F, sizeof(int) * 3 * (size_t)nf);
    memcpy(L->uv, uv0, sizeof(double) * 2 * (size_t)nv);
    L->total_area = 0.0;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        double a = tri2_rest_from_3d(V3 + 3 * (size_t)t[0], V3 + 3 * (size_t)t[1], V3 + 3 * (size_t)t[2],
                                     L->Dminv + 4 * (size_t)f);
        if (!(a > 0.0) || !isfinite(a)) {
            scaf_loop_free(L);
            return err_set(err, SCAF_ERR_MESH, "triangle %d has zero 3D area", f);
        }
        L->area[f] = a;
        L->total_area += a;
        if (!(orient2d(uv0 + 2 * (size_t)t[0], uv0 + 2 * (size_t)t[1], uv0 + 2 * (size_t)t[2]) > 0.0)) {
            scaf_loop_free(L);
            return err_set(err, SCAF_ERR_INTERNAL, "initial UV triangle %d is not positively oriented", f);
        }
    }
    scaf_status st = boundary_edges(nf, F, &L->bedges, &L->nbedges, err);
    if (st != SCAF_OK) {
        scaf_loop_free(L);
        return st;
    }
    if (L->nbedges == 0) {
        scaf_loop_free(L);
        return err_set(err, SCAF_ERR_MESH, "the mesh has no boundary (closed surface)");
    }
    return SCAF_OK;
}

/* ---- energies ---------------------------------------------------------- */

static double face_sd(const scaf_loop *L, const double *uv, int f)
{
    const int *t = L->F + 3 * f;
    double J[4];
    tri2_jacobian(uv + 2 * (size_t)t[0], uv + 2 * (size_t)t[1], uv + 2 * (size_t)t[2],
                  L->Dminv + 4 * (size_t)f, J);
    return tri2_energy(SCAF_ENERGY_SYMMETRIC_DIRICHLET, J);
}

double scaf_loop_energy(const scaf_loop *L)
{
    double s = 0.0;
    for (int f = 0; f < L->nf; f++) s += L->area[f] * face_sd(L, L->uv, f);
    return s / L->total_area;
}

void scaf_loop_face_energy(const scaf_loop *L, double *E)
{
    for (int f = 0; f < L->nf; f++) E[f] = face_sd(L, L->uv, f);
}

scaf_status scaf_loop_scaffold(const scaf_loop *L, scaffold *sc, scaf_error *err)
{
    scaffold_options so = {L->opt.box_scale, L->opt.box_square, L->opt.box_points_per_side,
                           L->opt.min_angle_deg};
    double box[4];
    scaffold_box(L->uv, L->nv, so.box_scale, so.box_square, box);
    return scaffold_build(L->uv, L->nv, L->bedges, L->nbedges, box, &so, sc, err);
}

/* The elements of the total energy: mesh faces then scaffold triangles. */
typedef struct elements {
    int n, nmesh;
    const int *Fm;        /* mesh faces */
    const int *Ts;        /* scaffold triangles */
    const double *Dm;     /* mesh rest frames */
    const double *Ds;     /* scaffold rest frames */
    const double *wm;     /* mesh weights (areas) */
    double ws;            /* scaffold weight (lambda) */
    scaf_energy em;       /* mesh energy */
} elements;

static inline const int *el_tri(const elements *e, int i)
{
    return i < e->nmesh ? e->Fm + 3 * (size_t)i : e->Ts + 3 * (size_t)(i - e->nmesh);
}
static inline const double *el_rest(const elements *e, int i)
{
    return i < e->nmesh ? e->Dm + 4 * (size_t)i : e->Ds + 4 * (size_t)(i - e->nmesh);
}
static inline double el_weight(const elements *e, int i) { return i < e->nmesh ? e->wm[i] : e->ws; }
static inline scaf_energy el_energy(const elements *e, int i)
{
    return i < e->nmesh ? e->em : SCAF_ENERGY_SYMMETRIC_DIRICHLET;
}

/* Total energy at positions P (all vertex ids); +inf if any triangle is
 * not positively oriented (floating-point determinant). */
static double total_energy(const elements *e, const double *P)
{
    double s = 0.0;
    for (int i = 0; i < e->n; i++) {
        const int *t = el_tri(e, i);
        double J[4];
        tri2_jacobian(P + 2 * (size_t)t[0], P + 2 * (size_t)t[1], P + 2 * (size_t)t[2], el_rest(e, i), J);
        double v = tri2_energy(el_energy(e, i), J);
        if (!isfinite(v)) return INFINITY;
        s += el_weight(e, i) * v;
    }
    return s;
}

/* Directional derivative of the total energy at P along D. */
static double total_slope(const elements *e, const double *P, const double *D)
{
    double s = 0.0;
    for (int i = 0; i < e->n; i++) {
        const int *t = el_tri(e, i);
        double J[4], dJ[4], G[4];
        tri2_jacobian(P + 2 * (size_t)t[0], P + 2 * (size_t)t[1], P + 2 * (size_t)t[2], el_rest(e, i), J);
        tri2_jacobian(D + 2 * (size_t)t[0], D + 2 * (size_t)t[1], D + 2 * (size_t)t[2], el_rest(e, i), dJ);
        tri2_energy_grad(el_energy(e, i), J, G);
        s += el_weight(e, i) * (G[0] * dJ[0] + G[1] * dJ[1] + G[2] * dJ[2] + G[3] * dJ[3]);
    }
    return s;
}

static int all_positive(const elements *e, const double *P)
{
    for (int i = 0; i < e->n; i++) {
        const int *t = el_tri(e, i);
        if (!(orient2d(P + 2 * (size_t)t[0], P + 2 * (size_t)t[1], P + 2 * (size_t)t[2]) > 0.0)) return 0;
    }
    return 1;
}

/* ---- one iteration ----------------------------------------------------- */

scaf_status scaf_loop_step(scaf_loop *L, scaf_iteration_info_t *info, scaf_error *err)
{
    scaf_iteration_info_t I;
    memset(&I, 0, sizeof I);
    double t_start = now_seconds(), t0 = t_start, t1;
    scaf_status st = SCAF_OK;
    cholmod_common *c = L->chol;
    cholmod_triplet *Tr = NULL;
    cholmod_sparse *A = NULL;
    cholmod_factor *Lf = NULL;
    cholmod_dense *B = NULL, *X = NULL;
    double *P = NULL, *D = NULL, *Pt = NULL, *Dsc = NULL, *rhs = NULL;
    int *unk = NULL;

    I.energy_before = scaf_loop_energy(L);
    double EM = 0.0;
    for (int f = 0; f < L->nf; f++) {
        const int *t = L->F + 3 * f;
        double J[4];
        tri2_jacobian(L->uv + 2 * (size_t)t[0], L->uv + 2 * (size_t)t[1], L->uv + 2 * (size_t)t[2],
                      L->Dminv + 4 * (size_t)f, J);
        EM += L->area[f] * tri2_energy(L->opt.energy, J);
    }
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_OTHER] += t1 - t0;
    t0 = t1;

    /* ---- scaffold -------------------------------------------------------- */
    scaffold_free(&L->sc);
    st = scaf_loop_scaffold(L, &L->sc, err);
    if (st != SCAF_OK) goto done;
    scaffold *sc = &L->sc;
    int nall = L->nv + sc->nextra;
    double lambda = L->opt.lambda_ratio * EM / (sc->ntri > 0 ? sc->ntri : 1);
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_SCAFFOLD] += t1 - t0;
    t0 = t1;

    /* ---- positions, unknown numbering, scaffold rest frames ------------- */
    P = malloc(sizeof(double) * 2 * (size_t)nall);
    D = calloc(2 * (size_t)nall, sizeof(double));
    Pt = malloc(sizeof(double) * 2 * (size_t)nall);
    Dsc = malloc(sizeof(double) * 4 * (size_t)(sc->ntri ? sc->ntri : 1));
    unk = malloc(sizeof(int) * (size_t)nall);
    if (!P || !D || !Pt || !Dsc || !unk) {
        st = err_nomem(err, "SCAF iteration");
        goto done;
    }
    memcpy(P, L->uv, sizeof(double) * 2 * (size_t)L->nv);
    memcpy(P + 2 * (size_t)L->nv, sc->extra_uv, sizeof(double) * 2 * (size_t)sc->nextra);
    int nunk = 0;
    for (int v = 0; v < nall; v++)
        unk[v] = (v >= L->nv && sc->extra_fixed[v - L->nv]) ? -1 : nunk++;
    for (int s = 0; s < sc->ntri; s++) {
        const int *t = sc->T + 3 * s;
        tri2_rest_from_2d(P + 2 * (size_t)t[0], P + 2 * (size_t)t[1], P + 2 * (size_t)t[2], sc->eps,
                          Dsc + 4 * (size_t)s);
    }
    elements el = {L->nf + sc->ntri, L->nf, L->F, sc->T, L->Dminv, Dsc, L->area, lambda, L->opt.energy};

    /* ---- assembly -------------------------------------------------------- */
    size_t n = 2 * (size_t)nunk;
    size_t maxnz = 21 * (size_t)el.n;
    Tr = cholmod_allocate_triplet(n, n, maxnz, 1, CHOLMOD_REAL, c);
    rhs = calloc(n ? n : 1, sizeof(double));
    if (!Tr || !rhs) {
        st = err_nomem(err, "SCAF system");
        goto done;
    }
    int *Ti = Tr->i, *Tj = Tr->j;
    double *Tx = Tr->x;
    size_t nz = 0;
    for (int e = 0; e < el.n; e++) {
        const int *t = el_tri(&el, e);
        const double *Dm = el_rest(&el, e);
        double J[4], W[4], R[4], K[36], b[6];
        tri2_jacobian(P + 2 * (size_t)t[0], P + 2 * (size_t)t[1], P + 2 * (size_t)t[2], Dm, J);
        tri2_slim_weights(el_energy(&el, e), J, W, R);
        tri2_slim_element(el_weight(&el, e), Dm, W, R, K, b);
        for (int i = 0; i < 3; i++) {
            int ui = unk[t[i]];
            if (ui < 0) continue;
            for (int k = 0; k < 2; k++) {
                int row = 2 * ui + k;
                rhs[row] += b[2 * i + k];
                for (int j = 0; j < 3; j++) {
                    int uj = unk[t[j]];
                    for (int l = 0; l < 2; l++) {
                        double kv = K[(2 * i + k) * 6 + 2 * j + l];
                        if (uj < 0) {
                            rhs[row] -= kv * P[2 * (size_t)t[j] + l];
                            continue;
                        }
                        int col = 2 * uj + l;
                        if (row > col) continue;
                        Ti[nz] = row;
                        Tj[nz] = col;
                        Tx[nz] = kv;
                        nz++;
                    }
                }
            }
        }
    }
    Tr->nnz = nz;
    A = cholmod_triplet_to_sparse(Tr, nz, c);
    cholmod_free_triplet(&Tr, c);
    if (!A) {
        st = err_set(err, c->status == CHOLMOD_OUT_OF_MEMORY ? SCAF_ERR_NOMEM : SCAF_ERR_NUMERIC,
                     "assembling the SLIM system failed (CHOLMOD status %d)", c->status);
        goto done;
    }
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_ASSEMBLY] += t1 - t0;
    t0 = t1;

    /* ---- ordering, factorization, solve --------------------------------- */
    Lf = cholmod_analyze(A, c);
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_ANALYSIS] += t1 - t0;
    t0 = t1;
    if (!Lf || !cholmod_factorize(A, Lf, c) || c->status != CHOLMOD_OK) {
        st = err_set(err, c->status == CHOLMOD_OUT_OF_MEMORY ? SCAF_ERR_NOMEM : SCAF_ERR_NUMERIC,
                     "factorizing the SLIM system (%zu unknowns) failed (CHOLMOD status %d)", n,
                     c->status);
        goto done;
    }
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_FACTORIZATION] += t1 - t0;
    t0 = t1;
    B = cholmod_allocate_dense(n, 1, n, CHOLMOD_REAL, c);
    if (!B) {
        st = err_nomem(err, "SCAF right-hand side");
        goto done;
    }
    memcpy(B->x, rhs, sizeof(double) * n);
    X = cholmod_solve(CHOLMOD_A, Lf, B, c);
    if (!X) {
        st = err_set(err, SCAF_ERR_NUMERIC, "solving the SLIM system failed (CHOLMOD status %d)", c->status);
        goto done;
    }
    const double *x = X->x;
    for (int v = 0; v < nall; v++) {
        if (unk[v] < 0) continue;
        D[2 * (size_t)v] = x[2 * unk[v]] - P[2 * (size_t)v];
        D[2 * (size_t)v + 1] = x[2 * unk[v] + 1] - P[2 * (size_t)v + 1];
    }
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_SOLVE] += t1 - t0;
    t0 = t1;

    /* ---- line search ----------------------------------------------------- */
    double f0 = total_energy(&el, P);
    double slope = total_slope(&el, P, D);
    double tmax = INFINITY;
    for (int e = 0; e < el.n; e++) {
        const int *t = el_tri(&el, e);
        double m = tri2_max_step(P + 2 * (size_t)t[0], P + 2 * (size_t)t[1], P + 2 * (size_t)t[2],
                                 D + 2 * (size_t)t[0], D + 2 * (size_t)t[1], D + 2 * (size_t)t[2]);
        if (m < tmax) tmax = m;
    }
    double step = L->opt.step_fraction * tmax;
    if (step > 1.0) step = 1.0;
    double fa = f0;
    int accepted = 0;
    for (int tries = 0; tries < 64 && step > 0.0; tries++, step *= 0.5) {
        for (size_t k = 0; k < 2 * (size_t)nall; k++) Pt[k] = P[k] + step * D[k];
        double ft = total_energy(&el, Pt);
        int ok = slope < 0.0 ? ft <= f0 + 1e-4 * step * slope : ft < f0;
        if (!ok || !isfinite(ft)) continue;
        if (!all_positive(&el, Pt)) continue;
        fa = ft;
        accepted = 1;
        break;
    }
    if (!accepted) step = 0.0;
    else {
        memcpy(L->uv, Pt, sizeof(double) * 2 * (size_t)L->nv);
        memcpy(sc->extra_uv, Pt + 2 * (size_t)L->nv, sizeof(double) * 2 * (size_t)sc->nextra);
    }
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_LINE_SEARCH] += t1 - t0;
    t0 = t1;

    L->iterations++;
    I.iteration = L->iterations;
    I.energy = scaf_loop_energy(L);
    I.total_before = f0;
    I.total_after = fa;
    I.lambda = lambda;
    I.step = step;
    I.scaffold_triangles = sc->ntri;
    I.scaffold_vertices = sc->nextra;

done:
    cholmod_free_triplet(&Tr, c);
    cholmod_free_sparse(&A, c);
    cholmod_free_factor(&Lf, c);
    cholmod_free_dense(&B, c);
    cholmod_free_dense(&X, c);
    free(P);
    free(D);
    free(Pt);
    free(Dsc);
    free(rhs);
    free(unk);
    t1 = now_seconds();
    I.phase_seconds[SCAF_PHASE_OTHER] += t1 - t0;
    I.seconds = t1 - t_start;
    if (info) *info = I;
    return st;
}
