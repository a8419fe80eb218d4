/* tools/cli_seams: --seams and the seams line (see cli_seams.h). */
#include "cli_seams.h"

#include <stdio.h>
#include <string.h>

#include "app/seam_source.h"

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
