/* tools/cli_png: the picture options shared by `scaf param` and `scaf atlas`:
 * --png FILE, --png-size N (16..16384), --checker [N] (optional number of
 * checker squares across the 3D bounding-box diagonal, default 20),
 * --png-plain (the picture alone: no legend, chart numbers or border; for
 * `scaf atlas` the PNG is then exactly the unit square, a texture).
 * Parsing only; the picture itself is app/uv_png. */
#ifndef SCAF_TOOLS_CLI_PNG_H
#define SCAF_TOOLS_CLI_PNG_H

#include "app/uv_png.h"

#define CLI_PNG_DEFAULT_CHECKER 20.0

typedef struct cli_png {
    const char *path;   /* --png FILE, or NULL */
    uv_png_options opt; /* size, checker (0 = none), outline */
    int size_given;
    int plain; /* --png-plain: no legend, numbers or border (a texture) */
} cli_png;

/* Defaults; unit_square as in uv_png_options. */
void cli_png_init(cli_png *p, int unit_square);

/* If argv[*i] is one of the options, take it (and its value, advancing
 * *i) and return 1; return 0 when it is not one of them; print a usage
 * error naming command cmd and return -1 on a bad value. */
int cli_png_option(const char *cmd, int argc, char **argv, int *i, cli_png *p);

/* After all options: 0, or -1 after printing why (--checker or --png-size
 * without --png). */
int cli_png_finish(const char *cmd, const cli_png *p);

#endif
