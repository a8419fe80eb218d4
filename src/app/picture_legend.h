/* app/picture_legend: what makes a picture readable without the manual:
 * the colour bar of the distortion scale with its energy ticks, the unit
 * square's border and the padding's length, chart numbers, captions.
 *
 * Drawn into pixel buffers of 3 (RGB) or 4 (RGBA, drawn pixels opaque)
 * bytes per pixel with app/pixel_font; sizes grow with the picture
 * (picture_legend_scale: one font pixel per 300 picture pixels, at least
 * two from 200 pixels on, one below). The colour bar runs left to right from E = 4 to
 * DISTORTION_SCALE_TOP through distortion_scale_colour_at, one column per
 * position, ticks at distortion_scale_ticks. Only
 * picture_legend_chart_numbers allocates (SCAF_ERR_NOMEM); the rest never
 * fails and clips to the buffer.
 */
#ifndef SCAF_APP_PICTURE_LEGEND_H
#define SCAF_APP_PICTURE_LEGEND_H

#include "app/uv_raster.h"
#include "base/error.h"

/* Font pixels for a picture width pixels wide. */
int picture_legend_scale(int width);

/* Rows of the strip below a picture of this width holding the colour bar
 * (energy) and/or the padding's bar (padding > 0); 0 when neither. */
int picture_legend_strip_height(int width, int energy, double padding);

/* The strip: rows y0 .. height - 1 made opaque white, then the colour bar
 * labelled "E" with its ticks (energy) and a line "PADDING" followed by a
 * bar padding_pixels long (> 0; at least one pixel is drawn). */
void picture_legend_strip(unsigned char *px, int width, int height, int channels, int y0,
                          int energy, double padding_pixels);

/* A one-pixel grey border around [x, x + w) by [y, y + h). */
void picture_legend_frame(unsigned char *px, int width, int height, int channels, int x, int y,
                          int w, int h);

/* A caption centred at the top of the panel [x, x + w), its top at y,
 * dark on a white box. */
void picture_legend_caption(unsigned char *px, int width, int height, int channels, int x, int y,
                            int w, const char *text);

/* The number of each chart (chart[f], >= 0) written at the centroid of its
 * largest triangle, where the label fits inside the chart's pixel box. */
scaf_status picture_legend_chart_numbers(uv_raster *r, const uv_raster_frame *fr, const double *uv,
                                         int nf, const int *F, const int *chart, scaf_error *err);

#endif /* SCAF_APP_PICTURE_LEGEND_H */
