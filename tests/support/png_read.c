/* tests/support/png_read: PNG reading through libpng's simplified API. */
#include "support/png_read.h"

#include <png.h>
#include <stdlib.h>
#include <string.h>

unsigned char *test_png_read(const char *path, int *width, int *height)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) return NULL;
    img.format = PNG_FORMAT_RGBA;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf) {
        png_image_free(&img);
        return NULL;
    }
    if (!png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        return NULL;
    }
    *width = (int)img.width;
    *height = (int)img.height;
    return buf;
}

unsigned test_png_pixel(const unsigned char *rgba, int width, int i, int j, int *alpha)
{
    const unsigned char *p = rgba + 4 * ((size_t)j * (size_t)width + (size_t)i);
    if (alpha) *alpha = p[3];
    return (unsigned)p[0] << 16 | (unsigned)p[1] << 8 | p[2];
}

void test_png_surface_pixels(const unsigned char *rgba, int width, int height, int x0, int w,
                             int *inside, int *drawn)
{
    *inside = *drawn = 0;
    for (int j = 0; j < height; j++)
        for (int i = x0; i < x0 + w; i++) {
            unsigned c = test_png_pixel(rgba, width, i, j, NULL);
            if (c == 0xffffffu) continue;
            ++*drawn;
            *inside += (c >> 16) > (c & 0xffu);
        }
}
