/* app/png_write: an RGBA pixel buffer saved as a PNG file (libpng).
 *
 * The file is written through app/atomic_file: it appears whole or not at
 * all (no partial file, no temporary left behind). Fails with
 * SCAF_ERR_IO naming the path and the reason (folder not writable, disk
 * full, encoder error), or SCAF_ERR_USAGE for an empty picture.
 */
#ifndef SCAF_APP_PNG_WRITE_H
#define SCAF_APP_PNG_WRITE_H

#include "base/error.h"

/* path    output file
 * width, height  picture size in pixels (>= 1)
 * rgba    height rows of width pixels, 4 bytes R G B A each, top row first */
scaf_status png_write_rgba(const char *path, int width, int height, const unsigned char *rgba,
                           scaf_error *err);

/* The same for an opaque picture: rgb holds 3 bytes R G B per pixel. */
scaf_status png_write_rgb(const char *path, int width, int height, const unsigned char *rgb,
                          scaf_error *err);

#endif /* SCAF_APP_PNG_WRITE_H */
