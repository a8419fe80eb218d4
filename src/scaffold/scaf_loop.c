/* scaffold/scaf_loop: the SCAF iteration (see scaf_loop.h).
 *
 * The numerics are opt's: the chart term (rest frames of the 3D triangles,
 * weight = 3D area) is built once; each iteration builds the scaffold
 * (scaffold/scaffold_build), its term (rest = current shape with the eps
 * guard, weight = lambda), and hands both to opt_slim_step, which keeps the
 * chart's proxy pattern, assembles, factors with CHOLMOD, solves and runs
 * the flip-free Armijo line search with exact orientation checks over
 * mesh AND scaffold. Vertex array X = the mesh vertices, then the scaffold
 * vertices; box vertices are fixed (dof -1), so mesh vertices keep dofs
 * 0..nv-1 in every iteration.
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
    scaffold_free(&L->sc);
    opt_slim_destroy(L->slim);
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
    opt_slim_options so;
    opt_slim_options_default(&so);
    so.ls.safety = L->opt.step_fraction;
    L->slim = opt_slim_create(&so, err);
    if (!L->slim) {
        scaf_loop_free(L);
        return err->code ? err->code : SCAF_ERR_NOMEM;
    }
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
    scaffold_options so = {L->opt.box_scale, L->opt.box_square, L->opt.box_points_per_side,
                           L->opt.min_angle_deg};
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

/* ---- one iteration ----------------------------------------------------- */

scaf_status scaf_loop_step(scaf_loop *L, scaf_iteration_info_t *info, scaf_error *err)
{
    scaf_iteration_info_t I;
    memset(&I, 0, sizeof I);
    double t_start = timer_now(), t0 = t_start, t1;
    scaf_status st = SCAF_OK;
    double *X = NULL;
    int *dof = NULL;
    unsigned char *fixed = NULL;

    I.energy_before = scaf_loop_energy(L);
    opt_term mesh_term = {&L->chart, to_opt_energy(L->opt.energy)};
    double EM = opt_term_energy(&mesh_term, L->uv);
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
    for (int s = 0; s < L->scaf.n; s++) L->scaf.weight[s] = lambda;
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_ASSEMBLY] += t1 - t0;
    t0 = t1;

    /* ---- SLIM: assembly, CHOLMOD, line search ----------------------------- */
    opt_term terms[2] = {mesh_term, {&L->scaf, OPT_ENERGY_SYMMETRIC_DIRICHLET}};
    int changed[2] = {0, 1};
    opt_slim_stats ss;
    st = opt_slim_step(L->slim, terms, 2, changed, nall, dof, nfree, X, &ss, err);
    if (st != SCAF_OK) goto done;
    I.phase_seconds[SCAF_PHASE_ASSEMBLY] += ss.t_assemble + ss.t_pattern;
    I.phase_seconds[SCAF_PHASE_ANALYSIS] += ss.t_analyze;
    I.phase_seconds[SCAF_PHASE_FACTORIZATION] += ss.t_factor;
    I.phase_seconds[SCAF_PHASE_SOLVE] += ss.t_solve;
    I.phase_seconds[SCAF_PHASE_LINE_SEARCH] += ss.t_line_search;
    double accounted = ss.t_assemble + ss.t_pattern + ss.t_analyze + ss.t_factor + ss.t_solve + ss.t_line_search;
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_OTHER] += (t1 - t0) - accounted > 0 ? (t1 - t0) - accounted : 0.0;
    t0 = t1;

    memcpy(L->uv, X, sizeof(double) * 2 * (size_t)L->nv);
    memcpy(sc->extra_uv, X + 2 * (size_t)L->nv, sizeof(double) * 2 * (size_t)sc->nextra);
    L->iterations++;
    I.iteration = L->iterations;
    I.energy = scaf_loop_energy(L);
    I.total_before = ss.ls.energy_before;
    I.total_after = ss.ls.step > 0 ? ss.ls.energy_after : ss.ls.energy_before;
    I.lambda = lambda;
    I.step = ss.ls.step;
    I.scaffold_triangles = sc->ntri;
    I.scaffold_vertices = sc->nextra;

done:
    free(X);
    free(dof);
    free(fixed);
    t1 = timer_now();
    I.phase_seconds[SCAF_PHASE_OTHER] += t1 - t0;
    I.seconds = t1 - t_start;
    if (info) *info = I;
    return st;
}
