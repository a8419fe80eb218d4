/* tools/edit_start: the layout `scaf edit` starts from (see the header). */
#include "edit_start.h"

#include <stdio.h>
#include <string.h>

#include "exit_codes.h"

int edit_start_name_ok(const char *start)
{
    return !strcmp(start, "auto") || !strcmp(start, "input") || !strcmp(start, "atlas") ||
        !strcmp(start, "layout");
}

static const char *start_said(scaf_drag_start s)
{
    return s == SCAF_DRAG_START_INPUT ? "its UVs"
        : s == SCAF_DRAG_START_ATLAS  ? "the atlas (`scaf atlas`)"
                                      : "circles on a grid";
}

int edit_start_layout(const char *in, const mesh *m, const char *start, double padding,
                      scaf_seams seams, int quiet, scaf_drag_t **out, edit_start_kind *from)
{
    *out = NULL;
    scaf_drag_options_t opt = scaf_drag_options_default();
    opt.padding = padding;
    opt.seams = seams;
    scaf_drag_start tries[2];
    int ntries = 0, automatic = !strcmp(start, "auto");
    if (automatic) {
        if (m->nuv > 0) tries[ntries++] = SCAF_DRAG_START_INPUT;
        tries[ntries++] = SCAF_DRAG_START_ATLAS;
    } else {
        tries[ntries++] = !strcmp(start, "input") ? SCAF_DRAG_START_INPUT
            : !strcmp(start, "atlas")             ? SCAF_DRAG_START_ATLAS
                                                  : SCAF_DRAG_START_LAYOUT;
    }
    if (tries[0] == SCAF_DRAG_START_INPUT && m->nuv == 0) {
        fprintf(stderr,
                "scaf edit: %s: --start input: the file has no texture coordinates (vt) to "
                "start from; --start auto (the default) starts from the atlas\n",
                in);
        return EXIT_USAGE;
    }
    scaf_status st = SCAF_OK;
    for (int t = 0; t < ntries; t++) {
        opt.start = tries[t];
        scaf_drag_t *d = scaf_drag_new(&opt);
        if (!d) {
            fprintf(stderr, "scaf edit: out of memory\n");
            return EXIT_NOMEM;
        }
        /* the vt give the seams of every start (as `scaf atlas`), and
         * the positions of the input start */
        st = scaf_drag_set_mesh(d, m->V, m->nv, m->F, m->nf, m->nuv ? m->UV : NULL, m->nuv,
                                m->nuv ? m->FT : NULL);
        if (st == SCAF_OK) {
            if (!quiet)
                fprintf(stderr, "scaf edit: %s: %d faces, %d charts, starting from %s\n", in, m->nf,
                        scaf_drag_chart_count(d), start_said(opt.start));
            *out = d;
            *from = opt.start == SCAF_DRAG_START_INPUT ? EDIT_START_FROM_INPUT
                : opt.start == SCAF_DRAG_START_ATLAS   ? EDIT_START_FROM_ATLAS
                                                       : EDIT_START_FROM_LAYOUT;
            return EXIT_OK;
        }
        if (t + 1 < ntries) {
            if (!quiet)
                fprintf(stderr, "scaf edit: %s: not starting from its UVs: %s\n", in,
                        scaf_drag_error(d));
        } else if (opt.start == SCAF_DRAG_START_INPUT && !automatic) {
            fprintf(stderr,
                    "scaf edit: %s: --start input: %s\nscaf edit: --start auto (the default) "
                    "starts from the atlas `scaf atlas` makes instead\n",
                    in, scaf_drag_error(d));
        } else {
            fprintf(stderr, "scaf edit: %s: %s\n", in, scaf_drag_error(d));
        }
        scaf_drag_destroy(d);
    }
    return exit_code_for(st);
}
