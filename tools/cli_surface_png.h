/* tools/cli_surface_png: the picture options of the 3D commands (`scaf
 * flow`, `scaf untangle`, ...): --png FILE and --png-size N (pixels of
 * each square panel, 16..4096, default 512), and the one call that draws
 * the panels (app/surface_render) into a declared output. */
#ifndef SCAF_TOOLS_CLI_SURFACE_PNG_H
#define SCAF_TOOLS_CLI_SURFACE_PNG_H

#include "app/surface_render.h"
#include "cli_options.h"
#include "cli_outputs.h"

typedef struct cli_surface_png {
    const char *path;           /* --png FILE, or NULL */
    surface_render_options opt; /* panel size, camera */
    int size_given;
    int size; /* --png-size from an option table (0: not given); cli_surface_png_finish applies it */
} cli_surface_png;

/* The lines of --help for the two options; WHAT says what the panels show. */
#define CLI_SURFACE_PNG_HELP(what)                                                                 \
    "  --png FILE         a picture: " what ",\n"                                                  \
    "                     flat shaded, seen from the front-top-right (y up), inside\n"             \
    "                     faces (where the surface passes through itself) in orange\n"             \
    "  --png-size N       pixels of each square panel, 16..4096 (default 512)\n"

/* The two options as table entries (tools/cli_options) writing into *p. */
#define CLI_SURFACE_PNG_OPTIONS(p, what)                                                           \
    CLI_STRING("png", 0, &(p)->path, "FILE",                                                       \
               "a picture: " what ",\nflat shaded, seen from the front-top-right (y up), inside "  \
               "faces (where the surface passes through itself) in orange"),                       \
        CLI_INT("png-size", 0, &(p)->size, "N", SURFACE_RENDER_MIN_SIZE, SURFACE_RENDER_MAX_SIZE,  \
                "pixels of each square panel, 16..4096 (default 512)")

void cli_surface_png_init(cli_surface_png *p);

/* If argv[*i] is one of the options, take it (and its value, advancing
 * *i) and return 1; 0 when it is not; print a usage error naming command
 * cmd and return -1 on a bad value. */
int cli_surface_png_option(const char *cmd, int argc, char **argv, int *i, cli_surface_png *p);

/* After all options: take the table's --png-size; 0, or -1 after printing
 * why (--png-size without --png). */
int cli_surface_png_finish(const char *cmd, cli_surface_png *p);

/* Draw the n panels into output k of outs (k < 0: nothing to do): 0, or
 * the exit status after printing why (cli_outputs_end). */
int cli_surface_png_write(cli_outputs *outs, int k, int n, const surface_view *s,
                          const cli_surface_png *p);

#endif
