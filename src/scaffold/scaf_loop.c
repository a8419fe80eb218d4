/* scaffold/scaf_loop: the SCAF iteration (see scaf_loop.h).
 *
 * The numerics are opt's pieces: the mesh term (rest frames of the 3D
 * triangles, weight = 3D area) is built once; each iteration the scaffold
 * provider refreshes the scaffold and the loop builds its term (rest =
 * current shape with the eps guard, weight = lambda); every term fills its
 * SLIM proxy block (opt/objective; the mesh term keeps its pattern), the
 * blocks are summed (opt/proxy_system), ordered, factored and solved by
 * opt/block_solver (which owns the ordering, reuse and regularization
 * policy), and opt's line search runs over all terms (flip-free bound,
 * Armijo, exact orientation checks over mesh AND scaffold). Vertex array
 * X = the mesh vertices, then the scaffold vertices; box vertices are
 * fixed (dof -1), so mesh vertices keep dofs 0..nv-1 in every iteration.
 *
 * The scaffold's proxy differs from its energy: a scaffold triangle starts
 * each iteration at its rest shape (J = R), where the SLIM weight of
 * symmetric Dirichlet tends to w = 2 (proxy curvature w^2 = 4); like the
 * reference implementation (libigl's scaf) we use w = 1 there, a 4x softer
 * scaffold in the proxy only, which lets the charts move further per
 * iteration (camel_b: E after 30 iterations about 4.124 instead of
 * 4.125-4.126). Guarded (degenerate) scaffold triangles keep the true
 * weights. The line search always uses the true energy.
 *
 * When a factorization fails (the proxy numerically indefinite), the
 * solver regularizes the system with mu diag(A) for growing mu; when the energy is not finite at the start of the
 * line search, the iteration reports a zero step (see slim_step).
 *
 * Newton steps (opt.solver; see newton_system) fill the same pattern with
 * the terms' Hessians — the scaffold with its TRUE weights — and -g; the
 * solution is the direction itself. Per-simplex projection alone converges
 * only linearly on curved surfaces (most triangles keep a negative twist
 * at the minimum: bench/RESULTS-newton.md), so after a full Newton step
 * the exact Hessian is tried first, the projected one when CHOLMOD finds
 * the exact sum not positive definite, then a diagonal shift (without
 * SLIM's mu diag(A) X rhs term: the unknown is a step, not a position).
 */
#include "scaffold/scaf_loop.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/half_edges.h"
#include "base/timer.h"
#include "geom/predicates.h"
#include "opt/block_solver.h"
#include "opt/line_search.h"
#include "opt/proxy_system.h"
#include "scaffold/scaffold_cdt.h"

/* ---- setup ------------------------------------------------------------- */

/* Edges used by exactly one face, oriented as in that face (chart on the
 * left), in increasing (smaller end, larger end) order. Chart topology was
 * validated by the caller. */
static scaf_status boundary_edges(int nv, int nf, const int *F, int **out, int *nout,
                                  scaf_error *err)
{
    size_t nh = nf > 0 ? 3 * (size_t)nf : 0;
    int *order = malloc(sizeof(int) * (nh ? nh : 1));
    int *e = malloc(sizeof(int) * 2 * (nh ? nh : 1));
    int count = 0;
    scaf_status st = order && e ? half_edges_sort(nv, nf, F, NULL, order, &count, err)
                                : err_nomem(err, "boundary edges");
    if (st != SCAF_OK) {
        free(order);
        free(e);
        return st;
    }
    int n = 0;
    for (int i = 0; i < count;) {
        int j = i + 1;
        while (j < count && half_edges_same_edge(F, order[i], order[j])) j++;
        if (j - i == 1) {
            e[2 * n] = F[order[i]];
            e[2 * n + 1] = F[half_edge_next(order[i])];
            n++;
        }
        i = j;
    }
    free(order);
    *out = e;
    *nout = n;
    return SCAF_OK;
}

/* ---- the loop's own state --------------------------------------------- */

struct scaf_loop_work {
    int mesh_k, scaf_k;  /* term indices (mesh_k -1 in a volume loop) */
    double energy_floor; /* volume loop: see scaf_loop_init_volume */
    int *kept;           /* volume loop: the last iteration's scaffold
                                    (n by 4 ids, then nextra fixed flags), to
                                    keep its pattern when it did not change */
    int kept_n, kept_nextra;
    scaffold_provider *scaffold; /* refreshed every iteration */
    scaffold_view view;          /* its current scaffold */
    opt_simplices scaf;          /* its rest frames (current shape), weight = lambda */
    double *scaf_pw;             /* |S| proxy weights of the scaffold (see the banner) */
    opt_simplex_term mesh_def, scaf_def;
    opt_obj_term terms[OPT_PROXY_MAX_BLOCKS]; /* mesh, scaffold, extra terms */
    int nterms;
    opt_proxy_system sys;     /* the sum of the terms' blocks */
    opt_block_solver *solver; /* the linear solve and all its reuse policy */
    double *rhs, *sol, *dir;
    size_t cap_n, cap_x;
    int newton_on;    /* auto: SLIM has slowed down, Newton from now on */
    int slim_steps;   /* SLIM iterations so far (auto's cap) */
    int newton_exact; /* the last Newton step was full: try the exact Hessian */
    /* The mesh term's energy (of kind seen_kind) and the reported E at the
     * positions seen_uv (nv by d), known from the last step's line search:
     * the next step starts there unless the caller moved the map. */
    double *seen_uv;
    double seen_em, seen_e;
    opt_energy seen_kind;
    int seen_valid;
    unsigned char *pinned; /* nv flags (NULL until a vertex is pinned) */
    int npinned;
};

scaf_loop_options scaf_loop_options_default(void)
{
    scaf_loop_options o;
    memset(&o, 0, sizeof o);
    o.energy = OPT_ENERGY_SYMMETRIC_DIRICHLET;
    o.lambda_ratio = 0.01;
    o.step_fraction = 0.8;
    o.scaffold = scaffold_default_options();
    o.solver = SCAF_SOLVER_SLIM;
    o.newton_switch = 1e-2;
    o.newton_after = 8;
    o.newton_lambda_scale = 0.1;
    return o;
}

void scaf_loop_free(scaf_loop *L)
{
    if (!L) return;
    free(L->F);
    free(L->uv);
    free(L->bedges);
    opt_simplices_free(&L->chart);
    free(L->chart_face);
    scaf_loop_work *w = L->work;
    if (w) {
        scaffold_provider_destroy(w->scaffold);
        opt_simplices_free(&w->scaf);
        free(w->scaf_pw);
        for (int k = 0; k < w->nterms; k++) opt_obj_term_free(&w->terms[k]);
        opt_proxy_system_free(&w->sys);
        opt_block_solver_destroy(w->solver);
        free(w->rhs);
        free(w->sol);
        free(w->dir);
        free(w->kept);
        free(w->seen_uv);
        free(w->pinned);
        free(w);
    }
    memset(L, 0, sizeof *L);
}

scaf_status scaf_loop_init(scaf_loop *L, int nv, const double *V3, int nf, const int *F,
                           const double *uv0, const scaf_loop_options *opt, scaf_error *err)
{
    memset(L, 0, sizeof *L);
    L->d = 2;
    L->nv = nv;
    L->nf = nf;
    L->opt = opt ? *opt : scaf_loop_options_default();
    L->F = malloc(sizeof(int) * 3 * (size_t)(nf ? nf : 1));
    L->uv = malloc(sizeof(double) * 2 * (size_t)(nv ? nv : 1));
    L->work = calloc(1, sizeof *L->work);
    if (!L->F || !L->uv || !L->work) {
        scaf_loop_free(L);
        return err_nomem(err, "SCAF loop");
    }
    memcpy(L->F, F, sizeof(int) * 3 * (size_t)nf);
    memcpy(L->uv, uv0, sizeof(double) * 2 * (size_t)nv);
    /* room for the energies' record (energy_after_step), taken now: made
     * among the iterations' large blocks, it kept ~3 MB more resident on
     * aphrodite */
    L->work->seen_uv = malloc(sizeof(double) * 2 * (size_t)(nv ? nv : 1));
    scaf_status st = opt_simplices_from_surface(&L->chart, nv, V3, nf, F, err);
    L->chart_face = malloc(sizeof(int) * (size_t)(nf ? nf : 1));
    if (st == SCAF_OK && !L->chart_face) st = err_nomem(err, "SCAF loop");
    if (st == SCAF_OK) st = opt_simplices_order_by_last_vertex(&L->chart, nv, L->chart_face, err);
    if (st == SCAF_OK) st = opt_simplices_permute(&L->chart, L->chart_face, err);
    if (st != SCAF_OK) {
        scaf_loop_free(L);
        return st;
    }
    L->total_area = 0.0;
    for (int f = 0; f < nf; f++) L->total_area += L->chart.weight[f];
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        if (!(orient2d(uv0 + 2 * (size_t)t[0], uv0 + 2 * (size_t)t[1], uv0 + 2 * (size_t)t[2]) >
              0.0)) {
            scaf_loop_free(L);
            return err_set(err, SCAF_ERR_INTERNAL,
                           "initial UV triangle %d is not positively oriented", f);
        }
    }
    st = boundary_edges(nv, nf, F, &L->bedges, &L->nbedges, err);
    if (st != SCAF_OK) {
        scaf_loop_free(L);
        return st;
    }
    if (L->nbedges == 0) {
        scaf_loop_free(L);
        return err_set(err, SCAF_ERR_MESH, "the mesh has no boundary (closed surface)");
    }
    scaf_loop_work *w = L->work;
    w->scaffold = scaffold_cdt_create(nv, L->bedges, L->nbedges, err);
    /* the mesh unknowns come first and keep their pattern */
    w->solver = w->scaffold ? opt_block_solver_create(L->d, L->d * L->nv, err) : NULL;
    if (!w->solver) {
        scaf_loop_free(L);
        return err && err->code ? err->code : SCAF_ERR_NOMEM;
    }
    w->mesh_def = (opt_simplex_term){&L->chart, L->opt.energy, NULL, 1};
    w->scaf_def = (opt_simplex_term){&w->scaf, OPT_ENERGY_SYMMETRIC_DIRICHLET, NULL, 0};
    w->mesh_k = 0;
    w->scaf_k = 1;
    w->terms[w->mesh_k] = opt_simplex_term_make(&w->mesh_def);
    w->terms[w->scaf_k] = opt_simplex_term_make(&w->scaf_def);
    w->nterms = 2;
    return SCAF_OK;
}

scaf_status scaf_loop_init_volume(scaf_loop *L, int nv, const double *X0, scaffold_provider *p,
                                  double energy_floor, const scaf_loop_options *opt,
                                  scaf_error *err)
{
    memset(L, 0, sizeof *L);
    if (!p || p->d != 3 || p->nmesh != nv || nv < 1 || !(energy_floor > 0.0) ||
        !isfinite(energy_floor)) {
        scaffold_provider_destroy(p);
        return err_set(err, SCAF_ERR_USAGE,
                       "SCAF volume loop: a 3D scaffold provider over %d vertices and an energy "
                       "floor > 0 (%g) are needed",
                       nv, energy_floor);
    }
    L->d = 3;
    L->nv = nv;
    L->opt = opt ? *opt : scaf_loop_options_default();
    L->uv = malloc(sizeof(double) * 3 * (size_t)nv);
    L->work = calloc(1, sizeof *L->work);
    if (!L->uv || !L->work) {
        scaffold_provider_destroy(p);
        scaf_loop_free(L);
        return err_nomem(err, "SCAF volume loop");
    }
    memcpy(L->uv, X0, sizeof(double) * 3 * (size_t)nv);
    scaf_loop_work *w = L->work;
    w->scaffold = p;
    w->solver = opt_block_solver_create(3, 3 * nv, err);
    if (!w->solver) {
        scaf_loop_free(L);
        return err && err->code ? err->code : SCAF_ERR_NOMEM;
    }
    w->mesh_k = -1;
    w->scaf_k = 0;
    w->energy_floor = energy_floor;
    w->scaf_def = (opt_simplex_term){&w->scaf, OPT_ENERGY_SYMMETRIC_DIRICHLET, NULL, 0};
    w->terms[w->scaf_k] = opt_simplex_term_make(&w->scaf_def);
    w->nterms = 1;
    return SCAF_OK;
}

scaf_status scaf_loop_set_scaffold_provider(scaf_loop *L, scaffold_provider *p, scaf_error *err)
{
    if (!p || p->d != L->d || p->nmesh != L->nv)
        return err_set(err, SCAF_ERR_USAGE,
                       "SCAF loop: a scaffold provider of dimension %d over %d mesh vertices is "
                       "needed",
                       L->d, L->nv);
    scaf_loop_work *w = L->work;
    scaffold_provider_destroy(w->scaffold);
    w->scaffold = p;
    memset(&w->view, 0, sizeof w->view);
    return SCAF_OK;
}

scaf_status scaf_loop_add_term(scaf_loop *L, const opt_obj_term *t, scaf_error *err)
{
    scaf_loop_work *w = L->work;
    if (!t || !t->ops || !t->ops->energy || !t->ops->energy_slope ||
        !t->ops->pattern != !t->ops->fill)
        return err_set(err, SCAF_ERR_USAGE,
                       "SCAF loop: a term needs energy and energy_slope, and pattern with fill");
    if (w->nterms >= OPT_PROXY_MAX_BLOCKS)
        return err_set(err, SCAF_ERR_USAGE, "SCAF loop: at most %d terms", OPT_PROXY_MAX_BLOCKS);
    w->terms[w->nterms] = *t;
    memset(&w->terms[w->nterms].blk, 0, sizeof w->terms[w->nterms].blk);
    w->nterms++;
    return SCAF_OK;
}

const scaffold_view *scaf_loop_scaffold_view(const scaf_loop *L) { return &L->work->view; }
opt_simplices *scaf_loop_scaffold_rest(scaf_loop *L) { return &L->work->scaf; }
double *scaf_loop_scaffold_proxy_weights(scaf_loop *L) { return L->work->scaf_pw; }
const opt_csc *scaf_loop_last_system(const scaf_loop *L) { return &L->work->sys.A; }
const int *scaf_loop_mesh_ordering(const scaf_loop *L)
{
    return opt_block_solver_fixed_ordering(L->work->solver);
}

int scaf_loop_newton_available(const scaf_loop *L)
{
    const scaf_loop_work *w = L->work;
    for (int k = 0; k < w->nterms; k++)
        if (w->terms[k].ops->fill && !w->terms[k].ops->hessian_fill) return 0;
    return 1;
}

/* ---- pinned vertices --------------------------------------------------- */

scaf_status scaf_loop_pin(scaf_loop *L, int v, int pinned, scaf_error *err)
{
    scaf_loop_work *w = L->work;
    if (v < 0 || v >= L->nv)
        return err_set(err, SCAF_ERR_USAGE, "SCAF loop: vertex %d to pin is not in [0, %d)", v,
                       L->nv);
    if (!w->pinned) {
        if (!pinned) return SCAF_OK;
        w->pinned = calloc((size_t)L->nv, 1);
        if (!w->pinned) return err_nomem(err, "pinned vertices");
    }
    pinned = pinned != 0;
    if (w->pinned[v] != pinned) w->npinned += pinned ? 1 : -1;
    w->pinned[v] = (unsigned char)pinned;
    return SCAF_OK;
}

int scaf_loop_pinned(const scaf_loop *L, int v)
{
    const scaf_loop_work *w = L->work;
    return w->pinned && v >= 0 && v < L->nv && w->pinned[v];
}

int scaf_loop_pinned_count(const scaf_loop *L) { return L->work->npinned; }

/* Orientation of triangle t (3 ids into the mesh vertices, then the
 * scaffold's extra vertices) with vertex v at p instead of its position. */
static double orient_with(const scaf_loop *L, const int *t, int v, const double p[2])
{
    const scaffold_view *sc = &L->work->view;
    const double *q[3];
    for (int k = 0; k < 3; k++)
        q[k] = t[k] == v   ? p
            : t[k] < L->nv ? L->uv + 2 * (size_t)t[k]
                           : sc->extra + 2 * (size_t)(t[k] - L->nv);
    return orient2d(q[0], q[1], q[2]);
}

int scaf_loop_place(scaf_loop *L, int v, const double p[2])
{
    const scaffold_view *sc = &L->work->view;
    if (L->d != 2 || v < 0 || v >= L->nv || !isfinite(p[0]) || !isfinite(p[1])) return 0;
    if (sc->n <= 0 || sc->nmesh != L->nv) return 0; /* no scaffold of the current map yet */
    for (int f = 0; f < L->nf; f++) {
        const int *t = L->F + 3 * (size_t)f;
        if ((t[0] == v || t[1] == v || t[2] == v) && !(orient_with(L, t, v, p) > 0.0)) return 0;
    }
    for (int s = 0; s < sc->n; s++) {
        const int *t = sc->simplices + 3 * (size_t)s;
        if ((t[0] == v || t[1] == v || t[2] == v) && !(orient_with(L, t, v, p) > 0.0)) return 0;
    }
    if (L->hooks.feasible) { /* e.g. the atlas's padding */
        int nall = L->nv + sc->nextra;
        double *X = malloc(sizeof(double) * 2 * (size_t)nall);
        if (!X) return 0;
        memcpy(X, L->uv, sizeof(double) * 2 * (size_t)L->nv);
        memcpy(X + 2 * (size_t)L->nv, sc->extra, sizeof(double) * 2 * (size_t)sc->nextra);
        X[2 * (size_t)v] = p[0];
        X[2 * (size_t)v + 1] = p[1];
        int ok = L->hooks.feasible(L->hooks.user, L, X, nall);
        free(X);
        if (!ok) return 0;
    }
    L->uv[2 * (size_t)v] = p[0];
    L->uv[2 * (size_t)v + 1] = p[1];
    return 1;
}

/* Pinned mesh vertices out of the assembled system (n unknowns): their
 * rows and columns zeroed but for a unit diagonal, their coupling to the
 * free unknowns moved to the right-hand side. The pattern stays (the
 * analysis is kept); the free unknowns get the minimizer of the proxy
 * with the pinned ones held. SLIM's unknowns are positions (rhs_i -=
 * a_ij X_j, the pinned rows solve to X_j); Newton's are steps (0 on the
 * pinned rows, nothing to move). Mesh vertex v owns unknowns d v .. d v +
 * d - 1 (box vertices are the only fixed dofs: see the banner). */
static void pins_eliminate(scaf_loop *L, const double *X, int newton, size_t n)
{
    scaf_loop_work *w = L->work;
    if (!w->npinned) return;
    opt_csc *A = &w->sys.A;
    size_t d = (size_t)L->d, nm = d * (size_t)L->nv;
    for (size_t c = 0; c < n; c++) {
        int pc = c < nm && w->pinned[c / d];
        for (int e = A->colptr[c]; e < A->colptr[c + 1]; e++) {
            size_t r = (size_t)A->rowidx[e];
            int pr = r < nm && w->pinned[r / d];
            if (!pc && !pr) continue;
            if (r == c) {
                A->val[e] = 1.0;
                continue;
            }
            if (!newton) {
                if (pc && !pr) w->rhs[r] -= A->val[e] * X[c];
                else if (pr && !pc) w->rhs[c] -= A->val[e] * X[r];
            }
            A->val[e] = 0.0;
        }
    }
    for (int v = 0; v < L->nv; v++)
        if (w->pinned[v])
            for (size_t a = 0; a < d; a++) w->rhs[d * (size_t)v + a] = newton ? 0.0 : X[d * v + a];
}

/* The step is exactly zero on pinned vertices, whatever the solve's
 * rounding. */
static void pins_zero_direction(const scaf_loop *L, double *dir)
{
    const scaf_loop_work *w = L->work;
    if (!w->npinned) return;
    for (int v = 0; v < L->nv; v++)
        if (w->pinned[v])
            for (int a = 0; a < L->d; a++) dir[(size_t)L->d * (size_t)v + a] = 0.0;
}

/* ---- energies ---------------------------------------------------------- */

/* Volume loop: the added terms' energy at the mesh positions. */
static double terms_energy(const scaf_loop *L)
{
    const scaf_loop_work *w = L->work;
    double e = 0.0;
    for (int k = 0; k < w->nterms; k++)
        if (k != w->scaf_k) e += w->terms[k].ops->energy(&w->terms[k], L->uv);
    return e;
}

double scaf_loop_energy(const scaf_loop *L)
{
    if (L->work->mesh_k < 0) return terms_energy(L);
    opt_term t = {&L->chart, OPT_ENERGY_SYMMETRIC_DIRICHLET};
    return opt_term_energy(&t, L->uv) / L->total_area;
}

double scaf_loop_mesh_energy(const scaf_loop *L)
{
    if (L->work->mesh_k < 0) return terms_energy(L);
    const opt_obj_term *t = &L->work->terms[L->work->mesh_k];
    return t->ops->energy(t, L->uv) / L->total_area;
}

void scaf_loop_face_energy(const scaf_loop *L, double *E)
{
    for (int s = 0; s < L->nf; s++) {
        double J[9];
        opt_jacobian(&L->chart, s, L->uv, J);
        E[L->chart_face[s]] = opt_density(OPT_ENERGY_SYMMETRIC_DIRICHLET, L->d, J);
    }
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

/* dir = the solution minus X for free vertices, 0 for fixed ones. */
static inline void direction(int d, int nall, const int *dof, const double *sol, const double *X,
                             double *dir)
{
    for (int v = 0; v < nall; v++)
        for (int a = 0; a < d; a++) {
            size_t i = (size_t)d * (size_t)v + a;
            dir[i] = dof[v] >= 0 ? sol[(size_t)d * (size_t)dof[v] + a] - X[i] : 0.0;
        }
}

/* dir = the solution (a Newton step) for free vertices, 0 for fixed ones. */
static void newton_direction(int d, int nall, const int *dof, const double *sol, double *dir)
{
    for (int v = 0; v < nall; v++)
        for (int a = 0; a < d; a++)
            dir[(size_t)d * (size_t)v + a] =
                dof[v] >= 0 ? sol[(size_t)d * (size_t)dof[v] + a] : 0.0;
}

/* Every term's Hessian (each simplex projected PSD when project) and -g
 * into its block and rhs, summed into the system. */
static scaf_status newton_fill(scaf_loop *L, const int *dof, const double *X, int project, size_t n,
                               scaf_error *err)
{
    scaf_loop_work *w = L->work;
    const opt_proxy_block *bl[OPT_PROXY_MAX_BLOCKS];
    int nb = 0;
    memset(w->rhs, 0, n * sizeof *w->rhs);
    for (int k = 0; k < w->nterms; k++) {
        opt_obj_term *t = &w->terms[k];
        if (!t->ops->fill) continue;
        scaf_status st = t->ops->hessian_fill(t, dof, X, project, w->rhs, err);
        if (st != SCAF_OK) return st;
        bl[nb++] = &t->blk;
    }
    scaf_status st = opt_proxy_system_sum(&w->sys, bl, nb, err);
    if (st == SCAF_OK) pins_eliminate(L, X, 1, n);
    return st;
}

/* The Newton system, ordered and factored: exact Hessian after a full
 * Newton step, projected when that is not positive definite (or from the
 * start), then diagonally shifted by the solver (banner). */
static scaf_status newton_system(scaf_loop *L, int nall, const int *dof, const double *X, size_t n,
                                 scaf_error *err)
{
    scaf_loop_work *w = L->work;
    int project = !w->newton_exact;
    opt_block_retry shift = {1, nall, dof, NULL}; /* the unknowns are steps */
    opt_block_retry none = {0, 0, NULL, NULL};
    scaf_status st = newton_fill(L, dof, X, project, n, err);
    if (st == SCAF_OK) st = opt_block_solver_update(w->solver, &w->sys, err);
    if (st == SCAF_OK)
        st = opt_block_solver_factor(w->solver, &w->sys, w->rhs, project ? &shift : &none, err);
    if (st == SCAF_ERR_NUMERIC && !project) {
        err_clear(err);
        st = newton_fill(L, dof, X, 1, n, err); /* the same pattern */
        if (st == SCAF_OK) st = opt_block_solver_factor(w->solver, &w->sys, w->rhs, &shift, err);
    }
    return st;
}

/* Assembly of every term's proxy (newton: Hessian), ordering,
 * factorization, solve and the line search over all terms. X (nall by d)
 * updated by the line search. */
static scaf_status slim_step(scaf_loop *L, int nall, const int *dof, int nfree, double *X,
                             int newton, slim_times *tm, opt_ls_result *ls, scaf_error *err)
{
    scaf_loop_work *w = L->work;
    int d = L->d;
    memset(tm, 0, sizeof *tm);
    memset(ls, 0, sizeof *ls);
    if (nfree < 1) return err_set(err, SCAF_ERR_INTERNAL, "SCAF: no free vertex");
    size_t n = (size_t)d * (size_t)nfree, nx = (size_t)d * (size_t)nall;
    scaf_status st;
    if (n > w->cap_n) {
        if ((st = grow(&w->rhs, n, err)) || (st = grow(&w->sol, n, err))) return st;
        w->cap_n = n;
    }
    if (nx > w->cap_x) {
        if ((st = grow(&w->dir, nx, err))) return st;
        w->cap_x = nx;
    }

    double t0 = timer_now();
    /* A block only spans the unknowns its term touches (the system sum
     * pads it to the full count); the mesh term keeps its pattern. */
    const opt_proxy_block *bl[OPT_PROXY_MAX_BLOCKS];
    int nb = 0;
    for (int k = 0; k < w->nterms; k++) {
        opt_obj_term *t = &w->terms[k];
        if (!t->ops->pattern) continue;
        st = t->ops->pattern(t, dof, nfree, err);
        if (st != SCAF_OK) return st;
    }
    opt_block_solver_times c0 = opt_block_solver_get_times(w->solver);
    if (newton) {
        /* assembly and factorization interleave (the fallbacks refill) */
        st = newton_system(L, nall, dof, X, n, err);
        if (st != SCAF_OK) return st;
    } else {
        memset(w->rhs, 0, n * sizeof *w->rhs);
        for (int k = 0; k < w->nterms; k++) {
            opt_obj_term *t = &w->terms[k];
            if (!t->ops->fill) continue;
            t->ops->fill(t, dof, X, w->rhs);
            bl[nb++] = &t->blk;
        }
        st = opt_proxy_system_sum(&w->sys, bl, nb, err);
        if (st != SCAF_OK) return st;
        pins_eliminate(L, X, 0, n);
        tm->assembly = timer_now() - t0;
        st = opt_block_solver_update(w->solver, &w->sys, err);
        opt_block_retry shrink = {1, nall, dof, X}; /* the unknowns are positions */
        if (st == SCAF_OK) st = opt_block_solver_factor(w->solver, &w->sys, w->rhs, &shrink, err);
    }
    if (st == SCAF_OK) st = opt_block_solver_solve(w->solver, w->sol, err);
    opt_block_solver_times c1 = opt_block_solver_get_times(w->solver);
    tm->analysis = c1.analysis - c0.analysis;
    tm->factor = c1.factor - c0.factor;
    tm->solve = c1.solve - c0.solve;
    if (newton) /* what the factorizations and orderings did not take */
        tm->assembly = timer_now() - t0 - tm->analysis - tm->factor - tm->solve;
    if (st != SCAF_OK) return st;

    double t4 = timer_now();
    if (newton) newton_direction(d, nall, dof, w->sol, w->dir);
    else if (d == 2) direction(2, nall, dof, w->sol, X, w->dir); /* d known: the loop unrolls */
    else direction(d, nall, dof, w->sol, X, w->dir);
    pins_zero_direction(L, w->dir);
    opt_ls_options lo;
    opt_ls_options_default(&lo);
    lo.safety = L->opt.step_fraction;
    st = opt_line_search(w->terms, w->nterms, d, nall, X, w->dir, &lo, ls, err);
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

    if (newton) w->newton_exact = ls->step == 1.0;
    tm->line_search = timer_now() - t4;
    return st;
}

/* ---- the feasibility hook: shorten a step it rejects -------------------- */

/* X holds the line search's result X0 + step * dir; halve the step until
 * the hook accepts, every term accepts X (exactly) and the total energy
 * is below its value at X0; otherwise restore X0 (step 0). */
static scaf_status feasible_backtrack(scaf_loop *L, int nall, const double *X0, double *X,
                                      opt_ls_result *ls)
{
    scaf_loop_work *w = L->work;
    if (!L->hooks.feasible || ls->step <= 0.0 || L->hooks.feasible(L->hooks.user, L, X, nall))
        return SCAF_OK;
    size_t nx = (size_t)L->d * (size_t)nall;
    double t = ls->step;
    for (int round = 0; round < 16 && L->hooks.restrict_dir; round++) {
        if (!L->hooks.restrict_dir(L->hooks.user, L, X, w->dir, nall)) break;
        for (size_t i = 0; i < nx; i++) X[i] = X0[i] + t * w->dir[i];
        double e = opt_obj_energy(w->terms, w->nterms, X);
        if (!(e < ls->energy_before) || !opt_obj_valid(w->terms, w->nterms, X)) break;
        if (L->hooks.feasible(L->hooks.user, L, X, nall)) {
            ls->energy_after = e;
            return SCAF_OK;
        }
    }
    for (int k = 0; k < 40; k++) {
        t *= 0.5;
        for (size_t i = 0; i < nx; i++) X[i] = X0[i] + t * w->dir[i];
        double e = opt_obj_energy(w->terms, w->nterms, X);
        if (e < ls->energy_before && opt_obj_valid(w->terms, w->nterms, X) &&
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

/* Signed area of triangle t at X (nall by 2); the expression of
 * opt_signed_volume, inline here where it runs once per scaffold triangle
 * and iteration. */
static inline double triangle_area(const double *X, const int *t)
{
    const double *a = X + 2 * (size_t)t[0], *b = X + 2 * (size_t)t[1], *c = X + 2 * (size_t)t[2];
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

/* Volume loop: a 3D scaffold usually keeps its tets from one iteration to
 * the next (scaffold/scaffold_tet), and then so does the term's pattern
 * (and CHOLMOD's analysis): tell the scaffold term to keep it. */
static scaf_status keep_same_pattern(scaf_loop_work *w, const scaffold_view *v, scaf_error *err)
{
    size_t nt = 4 * (size_t)v->n, need = nt + (size_t)v->nextra;
    int same = w->kept && w->kept_n == v->n && w->kept_nextra == v->nextra &&
        !memcmp(w->kept, v->simplices, nt * sizeof(int));
    for (int i = 0; same && i < v->nextra; i++) same = w->kept[nt + i] == v->extra_fixed[i];
    w->scaf_def.keep_pattern = same;
    if (same) return SCAF_OK;
    int *k = realloc(w->kept, (need ? need : 1) * sizeof *k);
    if (!k) return err_nomem(err, "SCAF volume loop");
    w->kept = k;
    memcpy(k, v->simplices, nt * sizeof(int));
    for (int i = 0; i < v->nextra; i++) k[nt + i] = v->extra_fixed[i];
    w->kept_n = v->n;
    w->kept_nextra = v->nextra;
    return SCAF_OK;
}

/* Rest shapes of the scaffold = current shapes (eps guard), energy weight
 * lambda, proxy weight lambda / 4 except on guarded simplices (banner). */
static scaf_status scaffold_term(scaf_loop *L, int nall, const double *X, double lambda,
                                 scaf_error *err)
{
    scaf_loop_work *w = L->work;
    const scaffold_view *v = &w->view;
    scaf_status st =
        opt_simplices_from_current(&w->scaf, L->d, nall, X, v->n, v->simplices, v->eps, err);
    if (st != SCAF_OK) {
        err_prefix(err, "scaffold rest shapes");
        return st;
    }
    free(w->scaf_pw);
    w->scaf_pw = malloc(sizeof(double) * (size_t)(v->n ? v->n : 1));
    w->scaf_def.proxy_weight = w->scaf_pw;
    if (!w->scaf_pw) return err_nomem(err, "scaffold weights");
    for (int s = 0; s < w->scaf.n; s++) {
        double vol = L->d == 2 ? triangle_area(X, v->simplices + 3 * (size_t)s)
                               : opt_signed_volume(&w->scaf, s, X);
        w->scaf.weight[s] = lambda;
        w->scaf_pw[s] = vol >= v->eps ? 0.25 * lambda : lambda;
    }
    return SCAF_OK;
}

/* Whether the mesh term's energy and the reported E at L->uv are those the
 * last step recorded (energy_after_step): the same positions, to the bit,
 * and the same kind of mesh energy. */
static int energies_seen(const scaf_loop *L)
{
    const scaf_loop_work *w = L->work;
    return w->seen_valid && w->seen_kind == L->opt.energy &&
        !memcmp(w->seen_uv, L->uv, sizeof(double) * (size_t)L->d * (size_t)L->nv);
}

/* The reported E after a step (L->uv updated), and the record
 * energies_seen checks at the next step. The mesh term's energy at the new
 * positions is the line search's own (the same function on the same
 * doubles: the same bits), or em_start when no step was taken; a
 * feasibility hook's backtracking (moved) moves X after the search, so
 * then E is computed afresh and nothing is recorded. */
static double energy_after_step(scaf_loop *L, const opt_ls_result *ls, double em_start, int moved)
{
    scaf_loop_work *w = L->work;
    int sd = L->opt.energy == OPT_ENERGY_SYMMETRIC_DIRICHLET, known = 0;
    double em = 0.0;
    w->seen_valid = 0;
    if (w->mesh_k >= 0 && !moved) {
        if (!(ls->step > 0.0)) {
            em = em_start;
            known = 1;
        } else if (ls->nterm_energy > w->mesh_k) {
            em = ls->term_energy[w->mesh_k];
            known = 1;
        }
    }
    double e = known && sd ? em / L->total_area : scaf_loop_energy(L);
    size_t n = (size_t)L->d * (size_t)L->nv;
    if (known && !w->seen_uv) w->seen_uv = malloc((n ? n : 1) * sizeof *w->seen_uv);
    if (known && w->seen_uv) { /* without the memory, no record: recompute */
        memcpy(w->seen_uv, L->uv, n * sizeof *w->seen_uv);
        w->seen_em = em;
        w->seen_e = e;
        w->seen_kind = L->opt.energy;
        w->seen_valid = 1;
    }
    return e;
}

scaf_status scaf_loop_step(scaf_loop *L, scaf_iteration_info_t *info, scaf_error *err)
{
    scaf_loop_work *w = L->work;
    int d = L->d;
    scaf_iteration_info_t I;
    memset(&I, 0, sizeof I);
    I.criterion = INFINITY; /* judged by the caller (opt/convergence) */
    double t_start = timer_now(), t0 = t_start, t1;
    scaf_status st = SCAF_OK;
    double *X = NULL, *X0 = NULL;
    int *dof = NULL;
    unsigned char *fixed = NULL;

    double EM, em_start = 0.0;
    if (w->mesh_k >= 0) {
        w->mesh_def.energy = L->opt.energy;
        const opt_obj_term *mesh_term = &w->terms[w->mesh_k];
        if (energies_seen(L)) {
            EM = w->seen_em;
            I.energy_before = w->seen_e;
        } else {
            EM = mesh_term->ops->energy(mesh_term, L->uv);
            /* The reported E is symmetric Dirichlet: reuse EM when that is
             * the optimized energy too. */
            I.energy_before = L->opt.energy == OPT_ENERGY_SYMMETRIC_DIRICHLET ? EM / L->total_area
                                                                              : scaf_loop_energy(L);
        }
        em_start = EM;
    } else {
        /* Volume loop: the scaffold weight follows the terms' energy plus
         * the floor, so it stays positive (scaf_loop_init_volume). */
        I.energy_before = terms_energy(L);
        EM = I.energy_before + w->energy_floor;
        if (!isfinite(EM)) {
            st = err_set(err, SCAF_ERR_NUMERIC, "SCAF volume loop: the energy is not finite");
            goto done;
        }
    }
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_OTHER] += t1 - t0;
    t0 = t1;

    /* ---- scaffold around the current boundary ----------------------------- */
    st = w->scaffold->ops->refresh(w->scaffold, L->uv, &L->opt.scaffold, err);
    opt_simplices_free(&w->scaf);
    w->scaffold->ops->view(w->scaffold, &w->view);
    if (st != SCAF_OK) goto done;
    const scaffold_view *sc = &w->view;
    int nall = L->nv + sc->nextra;
    if (w->mesh_k < 0) {
        st = keep_same_pattern(w, sc, err);
        if (st != SCAF_OK) goto done;
    }
    size_t nx = (size_t)d * (size_t)nall;
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_SCAFFOLD] += t1 - t0;
    t0 = t1;

    /* ---- positions, dofs, scaffold term ----------------------------------- */
    X = malloc(sizeof(double) * nx);
    dof = malloc(sizeof(int) * (size_t)nall);
    fixed = calloc((size_t)nall, 1);
    if (!X || !dof || !fixed) {
        st = err_nomem(err, "SCAF iteration");
        goto done;
    }
    memcpy(X, L->uv, sizeof(double) * d * (size_t)L->nv);
    memcpy(X + (size_t)d * L->nv, sc->extra, sizeof(double) * d * (size_t)sc->nextra);
    memcpy(fixed + L->nv, sc->extra_fixed, (size_t)sc->nextra);
    int nfree = opt_dof_numbering(nall, fixed, dof);
    int newton = (L->opt.solver == SCAF_SOLVER_NEWTON ||
                  (L->opt.solver == SCAF_SOLVER_AUTO && w->newton_on)) &&
        scaf_loop_newton_available(L);
    /* ARAP is 0 at a rotation: E_M alone shrinks towards 0 at the minimum
     * and the scaffold's weight with it, until the boundary squeezes the
     * scaffold into its barrier and every re-meshing moves the map (camel_b:
     * lambda 1.5e-7, no convergence in 200 iterations). E_M + area keeps
     * the weight per unit of the mesh term's curvature what symmetric
     * Dirichlet's E_M >= 4 area gives (ARAP's curvature at a rotation is 2,
     * a quarter of symmetric Dirichlet's 8); conformal's E_M >= area. */
    if (w->mesh_k >= 0) EM += opt_energy_scale_offset(L->opt.energy) * L->total_area;
    double lambda = L->opt.lambda_ratio * EM / (sc->n > 0 ? sc->n : 1);
    if (newton) lambda *= L->opt.newton_lambda_scale; /* see the option */
    st = scaffold_term(L, nall, X, lambda, err);
    if (st != SCAF_OK) goto done;
    if (L->hooks.prepare) {
        st = L->hooks.prepare(L->hooks.user, L, X, nall, err);
        if (st != SCAF_OK) goto done;
    }
    if (L->hooks.feasible) {
        X0 = malloc(sizeof(double) * nx);
        if (!X0) {
            st = err_nomem(err, "SCAF iteration");
            goto done;
        }
        memcpy(X0, X, sizeof(double) * nx);
    }
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_ASSEMBLY] += t1 - t0;
    t0 = t1;

    /* ---- SLIM or Newton: assembly, CHOLMOD, line search ------------------- */
    slim_times tm;
    opt_ls_result ls;
    for (;;) {
        st = slim_step(L, nall, dof, nfree, X, newton, &tm, &ls, err);
        I.phase_seconds[SCAF_PHASE_ASSEMBLY] += tm.assembly;
        I.phase_seconds[SCAF_PHASE_ANALYSIS] += tm.analysis;
        I.phase_seconds[SCAF_PHASE_FACTORIZATION] += tm.factor;
        I.phase_seconds[SCAF_PHASE_SOLVE] += tm.solve;
        I.phase_seconds[SCAF_PHASE_LINE_SEARCH] += tm.line_search;
        /* A Newton system that cannot be filled or factored (a simplex too
         * thin for floating point) or a direction that takes no step:
         * SLIM's proxy, always definite, takes this iteration (X is
         * unchanged after a zero step). */
        if (!newton || !(st == SCAF_ERR_NUMERIC || (st == SCAF_OK && ls.step <= 0.0))) break;
        err_clear(err);
        newton = 0;
        w->newton_exact = 0;
    }
    if (st == SCAF_OK && X0) st = feasible_backtrack(L, nall, X0, X, &ls);
    if (st != SCAF_OK) goto done;
    I.solver = newton ? SCAF_SOLVER_NEWTON : SCAF_SOLVER_SLIM;
    if (newton && ls.energy_before > 0.0) I.decrement = -ls.slope / (2.0 * ls.energy_before);
    /* auto: SLIM has slowed down (one iteration's relative decrease below
     * the threshold) or has had newton_after iterations, Newton from the
     * next iteration on */
    if (!newton) w->slim_steps++;
    if (!newton && L->opt.solver == SCAF_SOLVER_AUTO && ls.step > 0.0 &&
        (ls.energy_before - ls.energy_after < L->opt.newton_switch * ls.energy_before ||
         w->slim_steps >= L->opt.newton_after))
        w->newton_on = 1;
    t1 = timer_now();
    t0 = t1;

    /* pinned vertices keep their bits (X0 + t 0 turns -0.0 into +0.0) */
    for (int v = 0; w->npinned && v < L->nv; v++)
        if (w->pinned[v])
            for (int a = 0; a < d; a++)
                X[(size_t)d * (size_t)v + a] = L->uv[(size_t)d * (size_t)v + a];
    memcpy(L->uv, X, sizeof(double) * d * (size_t)L->nv);
    memcpy(sc->extra, X + (size_t)d * L->nv, sizeof(double) * d * (size_t)sc->nextra);
    L->iterations++;
    I.iteration = L->iterations;
    I.energy = energy_after_step(L, &ls, em_start, X0 != NULL);
    I.total_before = ls.energy_before;
    I.total_after = ls.step > 0 ? ls.energy_after : ls.energy_before;
    I.lambda = lambda;
    I.step = ls.step;
    I.scaffold_triangles = sc->n;
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
