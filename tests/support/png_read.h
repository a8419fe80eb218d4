/* tests/support/png_read: a PNG file read back with libpng, for tests of
 * the pictures scaf writes. */
#ifndef SCAF_TESTS_PNG_READ_H
#define SCAF_TESTS_PNG_READ_H

/* The picture as height rows of width RGBA pixels (caller frees), NULL
 * when the file is missing or not a valid PNG. */
unsigned char *test_png_read(const char *path, int *width, int *height);

/* The 0xRRGGBB colour of pixel (i, j), its alpha in *alpha (may be NULL). */
unsigned test_png_pixel(const unsigned char *rgba, int width, int i, int j, int *alpha);

/* In the columns [x0, x0 + w) of a picture of app/surface_render: how
 * many pixels show a surface (anything but the white background), and
 * how many of those show a face from inside (orange: red above blue). */
void test_png_surface_pixels(const unsigned char *rgba, int width, int height, int x0, int w,
                             int *inside, int *drawn);

#endif
