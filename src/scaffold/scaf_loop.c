/* scaffold/scaf_loop: the SCAF iteration (see scaf_loop.h).
 *
 * The numerics are opt's pieces: the chart term (rest frames of the 3D
 * triangles, weight = 3D area) is built once; each iteration builds the
 * scaffold (scaffold/scaffold_build) and its term (rest = current shape
 * with the eps guard, weight = lambda), fills the SLIM proxy blocks
 * (opt/proxy_block, the chart's element map kept), sums them
 * (opt/proxy_system), orders and factors with CHOLMOD (opt/cholmod_solver,
 * see order_and_factor for the ordering policy), solves, and runs opt's
 * flip-free Armijo line search with exact orientation checks over mesh AND
 * scaffold. Vertex array X = the mesh vertices, then the scaffold
 * vertices; box vertices are fixed (dof -1), so mesh vertices keep dofs
 * 0..nv-1 in every iteration.
 *
 * The step assembles the system itself (no generic driver) because the
 * scaffold's proxy differs from its energy: a scaffold triangle starts each
 * iteration at its rest shape (J = R), where the SLIM weight of symmetric
 * Dirichlet tends to w = 2 (proxy curvature w^2 = 4); like the reference
 * implementation (libigl's scaf) we use w = 1 there, a 4x softer scaffold
 * in the proxy only, which lets the charts move further per iteration
 * (camel_b: E after 30 iterations about 4.124 instead of 4.125-4.126).
 * Guarded (degenerate) scaffold triangles keep the true weights. The line
 * search always uses the true energy.
 */
#include "scaffold/scaf_loop.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/timer.h"
#include "geom/predicates.h"
#include "opt/energy.h"

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
    size_t nh = nf > 0 ? 3 * (size_t)nf : 0;
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
    free(L->bedges);
    opt_simplices_free(&L->chart);
    opt_simplices_free(&L->scaf);
    free(L->scaf_pw);
    scaffold_free(&L->sc);
    opt_proxy_block_free(&L->blk_chart);
    opt_proxy_block_free(&L->blk_scaf);
    opt_proxy_system_free(&L->sys);
    opt_chol_destroy(L->chol);
    free(L->mesh_perm);
    free(L->perm);
    free(L->rhs);
    free(L->sol);
    free(L->dir);
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
    if (!L->F || !L->uv) {
        scaf_loop_free(L);
        return err_nomem(err, "SCAF loop");
    }
    memcpy(L->F, F, sizeof(int) * 3 * (size_t)nf);
    memcpy(L->uv, uv0, sizeof(double) * 2 * (size_t)nv);
    scaf_status st = opt_simplices_from_surface(&L->chart, nv, V3, nf, F, err);
    if (st != SCAF_OK) {
        scaf_loop_free(L);
        return st;
    }
    L->total_area = 0.0;
    for (int f = 0; f < nf; f++) L->total_area += L->chart.weight[f];
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        if (!(orient2d(uv0 + 2 * (size_t)t[0], uv0 + 2 * (size_t)t[1], uv0 + 2 * (size_t)t[2]) > 0.0)) {
            scaf_loop_free(L);
            return err_set(err, SCAF_ERR_INTERNAL, "initial UV triangle %d is not positively oriented", f);
        }
    }
    st = boundary_edges(nf, F, &L->bedges, &L->nbedges, err);
    if (st != SCAF_OK) {
        scaf_loop_free(L);
        return st;
    }
    if (L->nbedges == 0) {
        scaf_loop_free(L);
        return err_set(err, SCAF_ERR_MESH, "the mesh has no boundary (closed surface)");
    }
    L->chol = opt_chol_create(OPT_ORDER_AMD, err);
    if (!L->chol) {
        scaf_loop_free(L);
        return err && err->code ? err->code : SCAF_ERR_NOMEM;
    }
    opt_chol_set_block(L->chol, 2);
    opt_chol_set_relax(L->chol, 4); /* bigger supernodes: faster (bench_factor) */
    return SCAF_OK;
}

/* ---- energies ---------------------------------------------------------- */

double scaf_loop_energy(const scaf_loop *L)
{
    opt_term t = {&L->chart, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    return opt_term_energy(&t, L->uv) / L->total_area;
}

void scaf_loop_face_energy(const scaf_loop *L, double *E)
{
    for (int f = 0; f < L->nf; f++) {
        double J[4];
        opt_jacobian(&L->chart, f, L->uv, J);
        E[f] = opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, 2, J);
    }
}

scaf_status scaf_loop_scaffold(const scaf_loop *L, scaffold *sc, scaf_error *err)
{
    scaffold_options so = scaffold_default_options();
    so.box_scale = L->opt.box_scale;
    so.box_square = L->opt.box_square;
    so.box_points_per_side = L->opt.box_points_per_side;
    so.min_angle_deg = L->opt.min_angle_deg;
    double box[4];
    scaffold_box(L->uv, L->nv, so.box_scale, so.box_square, box);
    return scaffold_build(L->uv, L->nv, L->bedges, L->nbedges, box, &so, sc, err);
}

static opt_energy to_opt_energy(scaf_energy e)
{
    switch (e) {
    case SCAF_ENERGY_ARAP: return OPT_ENERGY_ARAP;
    case SCAF_ENERGY_CONFORMAL: return OPT_ENERGY_CONFORMAL;
    case SCAF_ENERGY_SYMMETRIC_DIRICHLET: break;
    }
    return OPT_ENERGY_SYMMETRIC_DIRICHLET;
}

/* ---- the SLIM step ----------------------------------------------------- */

typedef struct slim_times {
    double assembly, analysis, factor, solve, line_search;
} slim_times;

static scaf_status grow(double **p, size_t n, scaf_error *err)
{
    double *q = realloc(*p, (n ? n : 1) * sizeof *q);
    if (!q) return err_nomem(err, "SLIM buffers");
    *p = q;
    return SCAF_OK;
}

/* Fill-reducing ordering, then factorization. The mesh part of the
 * pattern never changes, so its nested-dissection (METIS) order is computed
 * once, at the first iteration, and reused: the scaffold's unknowns go
 * last, which costs little while they are few. When the scaffold is large
 * (long, folded chart boundaries: hilbert.obj has 40% scaffold unknowns)
 * a trailing block that big would be nearly dense, so AMD orders the whole
 * system afresh instead. */
static scaf_status order_and_factor(scaf_loop *L, size_t n, double *t_metis, scaf_error *err)
{
    scaf_status st;
    size_t nm = 2 * (size_t)L->nv, nsc = n - nm;
    const int *given = NULL;
    if (!L->mesh_perm) {
        double t0 = timer_now();
        opt_chol *m = opt_chol_create(OPT_ORDER_METIS, err);
        if (!m) return err && err->code ? err->code : SCAF_ERR_NOMEM;
        opt_chol_set_block(m, 2); /* order vertices, not scalars */
        st = opt_chol_analyze_given(m, &L->sys.A, NULL, err);
        const int *p = opt_chol_permutation(m);
        L->mesh_perm = malloc(nm * sizeof *L->mesh_perm);
        int *q = realloc(L->perm, n * sizeof *q);
        if (q) {
            L->perm = q;
            L->cap_perm = n;
        }
        if (st == SCAF_OK && (!p || !L->mesh_perm || !q)) st = err_nomem(err, "ordering");
        if (st == SCAF_OK) {
            size_t k = 0;
            for (size_t i = 0; i < n; i++)
                if ((size_t)p[i] < nm) L->mesh_perm[k++] = p[i];
            memcpy(L->perm, p, n * sizeof *L->perm);
            given = L->perm;
        }
        opt_chol_destroy(m);
        *t_metis = timer_now() - t0;
        if (st != SCAF_OK) return st;
    } else if (nsc <= 256 || nsc * 50 <= n) {
        if (n > L->cap_perm) {
            int *q = realloc(L->perm, n * sizeof *q);
            if (!q) return err_nomem(err, "ordering");
            L->perm = q;
            L->cap_perm = n;
        }
        memcpy(L->perm, L->mesh_perm, nm * sizeof *L->perm);
        for (size_t k = nm; k < n; k++) L->perm[k] = (int)k;
        given = L->perm;
    }
    /* A scaffold identical to the last one (late iterations, the boundary
     * barely moving) gives the same pattern: keep that analysis. */
    if (!opt_chol_pattern_matches(L->chol, &L->sys.A)) {
        st = opt_chol_analyze_given(L->chol, &L->sys.A, given, err);
        if (st != SCAF_OK) return st;
    }
    return opt_chol_factor(L->chol, &L->sys.A, err);
}

/* Factor A + mu diag(A) with rhs + mu diag(A) x for growing mu, after a
 * plain factorization failed (see the caller). */
static scaf_status regularized_factor(scaf_loop *L, int nall, const int *dof, const double *X, size_t n,
                                      scaf_error *err)
{
    opt_csc *A = &L->sys.A;
    double *d0 = malloc(n * sizeof *d0), *r0 = malloc(n * sizeof *r0);
    int *pos = malloc(n * sizeof *pos);
    if (!d0 || !r0 || !pos) {
        free(d0);
        free(r0);
        free(pos);
        return err_nomem(err, "regularized system");
    }
    for (size_t c = 0; c < n; c++) {
        int e = A->colptr[c + 1] - 1;
        pos[c] = (e >= A->colptr[c] && A->rowidx[e] == (int)c) ? e : -1;
        d0[c] = pos[c] >= 0 ? A->val[e] : 0.0;
    }
    memcpy(r0, L->rhs, n * sizeof *r0);
    scaf_status st = SCAF_ERR_NUMERIC;
    for (double mu = 1e-10; st == SCAF_ERR_NUMERIC && mu < 10.0; mu *= 1000.0) {
        for (size_t c = 0; c < n; c++)
            if (pos[c] >= 0) A->val[pos[c]] = d0[c] * (1.0 + mu);
        for (int v = 0; v < nall; v++)
            if (dof[v] >= 0)
                for (int a = 0; a < 2; a++) {
                    size_t c = 2 * (size_t)dof[v] + a;
                    L->rhs[c] = r0[c] + mu * d0[c] * X[2 * (size_t)v + a];
                }
        err_clear(err);
        st = opt_chol_factor(L->chol, A, err);
    }
    free(d0);
    free(r0);
    free(pos);
    return st;
}

/* terms[0] chart, terms[1] scaffold (true energy); the scaffold's proxy
 * uses the weights L->scaf_pw. X (nall by 2) updated by the line search. */
static scaf_status slim_step(scaf_loop *L, const opt_term *terms, int nall, const int *dof, int nfree,
                             double *X, slim_times *tm, opt_ls_result *ls, scaf_error *err)
{
    memset(tm, 0, sizeof *tm);
    memset(ls, 0, sizeof *ls);
    if (nfree < 1) return err_set(err, SCAF_ERR_INTERNAL, "SCAF: no free vertex");
    size_t n = 2 * (size_t)nfree, nx = 2 * (size_t)nall;
    scaf_status st;
    if (n > L->cap_n) {
        if ((st = grow(&L->rhs, n, err)) || (st = grow(&L->sol, n, err))) return st;
        L->cap_n = n;
    }
    if (nx > L->cap_x) {
        if ((st = grow(&L->dir, nx, err))) return st;
        L->cap_x = nx;
    }

    double t0 = timer_now();
    /* The chart's pattern never changes: mesh vertices keep dofs
     * 0..nv-1 in every iteration and a block only spans the unknowns its
     * simplices touch (the system sum pads it to the full count). */
    if (!L->blk_chart.A.colptr || L->blk_chart.nfree > nfree) {
        st = opt_proxy_block_pattern(&L->blk_chart, terms[0].s, dof, nfree, err);
        if (st != SCAF_OK) return st;
    }
    st = opt_proxy_block_pattern(&L->blk_scaf, terms[1].s, dof, nfree, err);
    if (st != SCAF_OK) return st;
    opt_simplices proxy = *terms[1].s;
    proxy.weight = L->scaf_pw;
    opt_term pterm = {&proxy, terms[1].energy};
    memset(L->rhs, 0, n * sizeof *L->rhs);
    opt_proxy_block_fill(&L->blk_chart, &terms[0], dof, X, L->rhs);
    opt_proxy_block_fill(&L->blk_scaf, &pterm, dof, X, L->rhs);
    const opt_proxy_block *bl[2] = {&L->blk_chart, &L->blk_scaf};
    st = opt_proxy_system_sum(&L->sys, bl, 2, err);
    if (st != SCAF_OK) return st;
    tm->assembly = timer_now() - t0;

    opt_chol_stats c0 = opt_chol_get_stats(L->chol);
    double t_metis = 0.0;
    st = order_and_factor(L, n, &t_metis, err);
    if (st == SCAF_ERR_NUMERIC) st = regularized_factor(L, nall, dof, X, n, err);
    if (st == SCAF_OK) st = opt_chol_solve(L->chol, 1, L->rhs, L->sol, err);
    opt_chol_stats c1 = opt_chol_get_stats(L->chol);
    tm->analysis = c1.t_analyze - c0.t_analyze + t_metis;
    tm->factor = c1.t_factor - c0.t_factor;
    tm->solve = c1.t_solve - c0.t_solve;
    if (st != SCAF_OK) return st;

    double t4 = timer_now();
    for (int v = 0; v < nall; v++)
        for (int a = 0; a < 2; a++)
            L->dir[2 * (size_t)v + a] = dof[v] >= 0 ? L->sol[2 * (size_t)dof[v] + a] - X[2 * (size_t)v + a] : 0.0;
    opt_ls_options lo;
    opt_ls_options_default(&lo);
    lo.safety = L->opt.step_fraction;
    st = opt_line_search(terms, 2, 2, nall, X, L->dir, &lo, ls, err);
    if (st == SCAF_ERR_NUMERIC) {
        /* The energy is not finite in floating point at the current map (a
         * triangle exactly positive but too thin for its determinant to
         * round positive) or the direction is not finite: no step is safe
         * to judge. X is unchanged and still bijective: report a zero step
         * (the run then stops) instead of failing. */
        err_clear(err);
        memset(ls, 0, sizeof *ls);
        st = SCAF_OK;
    }

    tm->line_search = timer_now() - t4;
    return st;
}

/* ---- the feasibility hook: shorten a step it rejects -------------------- */

/* X holds the line search's result X0 + step * dir; halve the step until
 * the hook accepts, every simplex is exactly positive and the total energy
 * is below its value at X0; otherwise restore X0 (step 0). */
static scaf_status feasible_backtrack(scaf_loop *L, const opt_term *terms, int nall, const double *X0,
                                      double *X, opt_ls_result *ls)
{
    if (!L->hooks.feasible || ls->step <= 0.0 || L->hooks.feasible(L->hooks.user, L, X, nall))
        return SCAF_OK;
    size_t nx = 2 * (size_t)nall;
    double t = ls->step;
    for (int round = 0; round < 16 && L->hooks.restrict_dir; round++) {
        if (!L->hooks.restrict_dir(L->hooks.user, L, X, L->dir, nall)) break;
        for (size_t i = 0; i < nx; i++) X[i] = X0[i] + t * L->dir[i];
        double e = opt_terms_energy(terms, 2, X);
        if (!(e < ls->energy_before) || !opt_terms_oriented(terms, 2, X, NULL, NULL)) break;
        if (L->hooks.feasible(L->hooks.user, L, X, nall)) {
            ls->energy_after = e;
            return SCAF_OK;
        }
    }
    for (int k = 0; k < 40; k++) {
        t *= 0.5;
        for (size_t i = 0; i < nx; i++) X[i] = X0[i] + t * L->dir[i];
        double e = opt_terms_energy(terms, 2, X);
        if (e < ls->energy_before && opt_terms_oriented(terms, 2, X, NULL, NULL) &&
            L->hooks.feasible(L->hooks.user, L, X, nall)) {
            ls->step = t;
            ls->energy_after = e;
            return SCAF_OK;
        }
    }
    memcpy(X, X0, nx * sizeof *X);
    ls->step = 0.0;
    ls->energy_after = ls->energy_before;
    return SCAF_OK;
}

/* ---- one iteration ----------------------------------------------------- */

scaf_status scaf_loop_step(scaf_loop *L, scaf_iteration_info_t *info, scaf_error *err)
{
    scaf_iteration_info_t I;
    memset(&I, 0, sizeof I);
    double t_start = timer_now(), t0 = t_start, t1;
    scaf_status st = SCAF_OK;
    double *X = NULL, *X0 = NULL;
    int *dof = NULL;
    unsigned char *fixed = NULL;

    opt_term mesh_term = {&L->chart, to_opt_energy(L->opt.energy)};
    double EM = opt_term_energy(&mesh_term, L->uv);
    /* The reported E is symmetric Dirichlet: reuse EM when that is the
     * optimized energy too. */
    I.energy_before = mesh_term.energy == OPT_ENERGY_SYMMETRIC_DIRICHLET ? EM / L->total_area
                                                                         : scaf_loop_energy(L);
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_OTHER] += t1 - t0;
    t0 = t1;

    /* ---- scaffold around the current boundary ----------------------------- */
    scaffold_free(&L->sc);
    opt_simplices_free(&L->scaf);
    st = scaf_loop_scaffold(L, &L->sc, err);
    if (st != SCAF_OK) goto done;
    scaffold *sc = &L->sc;
    int nall = L->nv + sc->nextra;
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_SCAFFOLD] += t1 - t0;
    t0 = t1;

    /* ---- positions, dofs, scaffold term ----------------------------------- */
    X = malloc(sizeof(double) * 2 * (size_t)nall);
    dof = malloc(sizeof(int) * (size_t)nall);
    fixed = calloc((size_t)nall, 1);
    if (!X || !dof || !fixed) {
        st = err_nomem(err, "SCAF iteration");
        goto done;
    }
    memcpy(X, L->uv, sizeof(double) * 2 * (size_t)L->nv);
    memcpy(X + 2 * (size_t)L->nv, sc->extra_uv, sizeof(double) * 2 * (size_t)sc->nextra);
    memcpy(fixed + L->nv, sc->extra_fixed, (size_t)sc->nextra);
    int nfree = opt_dof_numbering(nall, fixed, dof);
    st = opt_simplices_from_current(&L->scaf, 2, nall, X, sc->ntri, sc->T, sc->eps, err);
    if (st != SCAF_OK) {
        err_prefix(err, "scaffold rest shapes");
        goto done;
    }
    double lambda = L->opt.lambda_ratio * EM / (sc->ntri > 0 ? sc->ntri : 1);
    free(L->scaf_pw);
    L->scaf_pw = malloc(sizeof(double) * (size_t)(sc->ntri ? sc->ntri : 1));
    if (!L->scaf_pw) {
        st = err_nomem(err, "scaffold weights");
        goto done;
    }
    for (int s = 0; s < L->scaf.n; s++) {
        const int *t = sc->T + 3 * s;
        const double *a = X + 2 * (size_t)t[0], *b = X + 2 * (size_t)t[1], *c = X + 2 * (size_t)t[2];
        double area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        L->scaf.weight[s] = lambda;
        L->scaf_pw[s] = area >= sc->eps ? 0.25 * lambda : lambda; /* see the banner */
    }
    if (L->hooks.prepare) {
        st = L->hooks.prepare(L->hooks.user, L, X, nall, err);
        if (st != SCAF_OK) goto done;
    }
    if (L->hooks.feasible) {
        X0 = malloc(sizeof(double) * 2 * (size_t)nall);
        if (!X0) {
            st = err_nomem(err, "SCAF iteration");
            goto done;
        }
        memcpy(X0, X, sizeof(double) * 2 * (size_t)nall);
    }
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_ASSEMBLY] += t1 - t0;
    t0 = t1;

    /* ---- SLIM: assembly, CHOLMOD, line search ----------------------------- */
    opt_term terms[2] = {mesh_term, {&L->scaf, OPT_ENERGY_SYMMETRIC_DIRICHLET}};
    slim_times tm;
    opt_ls_result ls;
    st = slim_step(L, terms, nall, dof, nfree, X, &tm, &ls, err);
    if (st == SCAF_OK && X0) st = feasible_backtrack(L, terms, nall, X0, X, &ls);
    if (st != SCAF_OK) goto done;
    I.phase_seconds[SCAF_PHASE_ASSEMBLY] += tm.assembly;
    I.phase_seconds[SCAF_PHASE_ANALYSIS] += tm.analysis;
    I.phase_seconds[SCAF_PHASE_FACTORIZATION] += tm.factor;
    I.phase_seconds[SCAF_PHASE_SOLVE] += tm.solve;
    I.phase_seconds[SCAF_PHASE_LINE_SEARCH] += tm.line_search;
    t1 = timer_now();
    t0 = t1;

    memcpy(L->uv, X, sizeof(double) * 2 * (size_t)L->nv);
    memcpy(sc->extra_uv, X + 2 * (size_t)L->nv, sizeof(double) * 2 * (size_t)sc->nextra);
    L->iterations++;
    I.iteration = L->iterations;
    I.energy = scaf_loop_energy(L);
    I.total_before = ls.energy_before;
    I.total_after = ls.step > 0 ? ls.energy_after : ls.energy_before;
    I.lambda = lambda;
    I.step = ls.step;
    I.scaffold_triangles = sc->ntri;
    I.scaffold_vertices = sc->nextra;

done:
    free(X);
    free(X0);
    free(dof);
    free(fixed);
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_OTHER] += t1 - t0;
    I.seconds = t1 - t_start;
    if (info) *info = I;
    return st;
}
