/* tools/cli_png: the picture options shared by `scaf param` and `scaf atlas`:
 * --png FILE, --png-size N (16..16384), --checker [N] (optional number of
 * checker squares across the 3D bounding-box diagonal, default 20),
 * --png-plain (the picture alone: no legend, chart numbers or border; for
 * `scaf atlas` the PNG is then exactly the unit square, a texture).
 * Parsing only; the picture itself is app/uv_png. */
#ifndef SCAF_TOOLS_CLI_PNG_H
#define SCAF_TOOLS_CLI_PNG_H

#include "app/uv_png.h"
#include "cli_options.h"

#define CLI_PNG_DEFAULT_CHECKER 20.0

typedef struct cli_png {
    const char *path;   /* --png FILE, or NULL */
    uv_png_options opt; /* size, checker (0 = none), outline */
    int size_given;
    int plain; /* --png-plain: no legend, numbers or border (a texture) */
} cli_png;

/* The three options as table entries (tools/cli_options) writing into *p
 * (a cli_png); the help of --png is the caller's (what the picture shows). */
int cli_png_size_take(const char *cmd, const cli_option *o, const char *value);
int cli_png_checker_take(const char *cmd, const cli_option *o, const char *value);
#define CLI_PNG_OPTIONS(p, png_help)                                                               \
    CLI_STRING("png", 0, &(p)->path, "FILE", png_help),                                            \
        CLI_CALLBACK("png-size", 0, cli_png_size_take, (p), "N",                                   \
                     "longer PNG side in pixels (16..16384, default 1024)",                        \
                     .min = UV_PNG_MIN_SIZE, .max = UV_PNG_MAX_SIZE),                              \
        CLI_CALLBACK("checker", 0, cli_png_checker_take, (p), "N",                                 \
                     "PNG only (the SVG has none): shade the fill with a checkerboard on the 3D "  \
                     "surface, N squares across the bounding-box diagonal (default 20); "          \
                     "stretched or sheared squares show the distortion",                           \
                     .optional = 1, .min = 1, .max = 10000)

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
