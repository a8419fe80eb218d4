/* tools/cli_surface_png: parsing of --png, --png-size for the 3D commands,
 * and the write through cli_outputs (see cli_surface_png.h). */
#include "cli_surface_png.h"

#include <stdio.h>
#include <string.h>

#include "cli_args.h"

void cli_surface_png_init(cli_surface_png *p)
{
    p->path = NULL;
    p->opt = surface_render_options_default();
    p->size_given = 0;
    p->size = 0;
}

int cli_surface_png_option(const char *cmd, int argc, char **argv, int *i, cli_surface_png *p)
{
    const char *a = argv[*i];
    const char *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (strcmp(a, "--png") && strcmp(a, "--png-size")) return 0;
    if (!v) {
        fprintf(stderr, "scaf %s: %s needs a value (see --help)\n", cmd, a);
        return -1;
    }
    ++*i;
    if (!strcmp(a, "--png")) {
        p->path = v;
        return 1;
    }
    int n;
    if (!cli_parse_int(v, &n) || n < SURFACE_RENDER_MIN_SIZE || n > SURFACE_RENDER_MAX_SIZE) {
        fprintf(stderr, "scaf %s: --png-size '%s': give a whole number of pixels from %d to %d\n",
                cmd, v, SURFACE_RENDER_MIN_SIZE, SURFACE_RENDER_MAX_SIZE);
        return -1;
    }
    p->opt.width = p->opt.height = n;
    p->size_given = 1;
    return 1;
}

int cli_surface_png_finish(const char *cmd, cli_surface_png *p)
{
    if (p->size > 0) {
        p->opt.width = p->opt.height = p->size;
        p->size_given = 1;
    }
    if (!p->path && p->size_given) {
        fprintf(stderr, "scaf %s: --png-size draws into the PNG picture: give --png FILE as well\n",
                cmd);
        return -1;
    }
    return 0;
}

int cli_surface_png_write(cli_outputs *outs, int k, int n, const surface_view *s,
                          const cli_surface_png *p)
{
    if (k < 0) return 0;
    scaf_error err;
    err_clear(&err);
    const char *path = cli_outputs_begin(outs, k, &err);
    scaf_status st = path ? surface_render_png(path, n, s, &p->opt, &err) : SCAF_ERR_IO;
    return cli_outputs_end(outs, k, st, &err);
}
