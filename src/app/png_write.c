/* app/png_write: PNG encoding through libpng's simplified write API
 * (png_image_write_to_stdio: no setjmp/longjmp in our code) into an
 * atomic temporary file (see png_write.h). */
#include "app/png_write.h"

#include <png.h>
#include <string.h>

#include "base/atomic_file.h"

static scaf_status write_format(const char *path, int width, int height,
                                const unsigned char *pixels, png_uint_32 format, scaf_error *err)
{
    if (width < 1 || height < 1 || !pixels)
        return err_set(err, SCAF_ERR_USAGE, "%s: empty picture (%d x %d)", path, width, height);
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)width;
    img.height = (png_uint_32)height;
    img.format = format;
    if (!png_image_write_to_stdio(&img, a.f, 0, pixels, 0, NULL)) {
        err_set(err, SCAF_ERR_IO, "%s: PNG encoding failed: %s", path,
                img.message[0] ? img.message : "libpng error");
        png_image_free(&img);
        atomic_abort(&a);
        return SCAF_ERR_IO;
    }
    png_image_free(&img);
    return atomic_commit(&a, err);
}

scaf_status png_write_rgba(const char *path, int width, int height, const unsigned char *rgba,
                           scaf_error *err)
{
    return write_format(path, width, height, rgba, PNG_FORMAT_RGBA, err);
}

scaf_status png_write_rgb(const char *path, int width, int height, const unsigned char *rgb,
                          scaf_error *err)
{
    return write_format(path, width, height, rgb, PNG_FORMAT_RGB, err);
}
