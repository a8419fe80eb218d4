/* tools/cli_seams: --seams and the seams line (see cli_seams.h). */
#include "cli_seams.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/atlas_picture.h"
#include "app/atlas_report.h"
#include "app/seam_source.h"
#include "app/surface_render.h"
#include "exit_codes.h"

int cli_seams_parse(const char *v, scaf_seams *out)
{
    if (!strcmp(v, "input")) *out = SCAF_SEAMS_INPUT;
    else if (!strcmp(v, "auto")) *out = SCAF_SEAMS_AUTO;
    else if (!strcmp(v, "extend")) *out = SCAF_SEAMS_EXTEND;
    else return 0;
    return 1;
}

int cli_seams_report(const char *cmd, const mesh *m, const int *FT, scaf_seams used,
                     const char *why, int charts, int quiet, seam_edges *s)
{
    seam_edges own;
    if (!s) s = &own;
    scaf_error err;
    err_clear(&err);
    if (seam_edges_find(m->nv, m->V, m->nf, m->F, FT, s, &err) != SCAF_OK) {
        fprintf(stderr, "scaf %s: %s\n", cmd, err.message);
        return 1;
    }
    if (!quiet)
        fprintf(stderr,
                "scaf %s: seams: %s (%s), %d chart(s), %d seam edges, seam length %.3f "
                "(per sqrt(area))\n",
                cmd, seam_source_name(used), why && *why ? why : "-", charts, s->n, s->normalized);
    if (s == &own) seam_edges_free(s);
    return 0;
}

int cli_seams_png(cli_outputs *outs, int k, const mesh *m, const int *face_chart,
                  const seam_edges *s, const mesh *atlas)
{
    if (k < 0) return EXIT_OK;
    unsigned *col = malloc(sizeof(unsigned) * (size_t)(m->nf ? m->nf : 1));
    double *back = malloc(sizeof(double) * 3 * (size_t)(m->nv ? m->nv : 1));
    if (!col || !back) {
        free(col);
        free(back);
        fprintf(stderr, "scaf: out of memory\n");
        return EXIT_NOMEM;
    }
    for (int f = 0; f < m->nf; f++) col[f] = atlas_chart_colour(face_chart[f]);
    /* the back: turned half a turn about the vertical through the box centre */
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) lo[d] = hi[d] = m->nv ? m->V[d] : 0.0;
    for (int i = 0; i < m->nv; i++)
        for (int d = 0; d < 3; d++) {
            double x = m->V[3 * (size_t)i + d];
            if (x < lo[d]) lo[d] = x;
            if (x > hi[d]) hi[d] = x;
        }
    for (int i = 0; i < m->nv; i++) {
        const double *p = m->V + 3 * (size_t)i;
        double *q = back + 3 * (size_t)i;
        q[0] = lo[0] + hi[0] - p[0];
        q[1] = p[1];
        q[2] = lo[2] + hi[2] - p[2];
    }
    surface_view v[2] = {{m->nv, m->V, m->nf, m->F, col, s->n, s->ab, "front"},
                         {m->nv, back, m->nf, m->F, col, s->n, s->ab, "back"}};
    scaf_error err;
    err_clear(&err);
    const char *path = cli_outputs_begin(outs, k, &err);
    scaf_status st = !path ? SCAF_ERR_IO
        : atlas ? atlas_picture_png(path, v, atlas->nuv, atlas->UV, atlas->nf, atlas->FT, col,
                                    surface_render_options_default().width, &err)
                : surface_render_png(path, 2, v, NULL, &err);
    int rc = cli_outputs_end(outs, k, st, &err);
    free(col);
    free(back);
    return rc;
}
