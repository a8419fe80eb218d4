/* app/picture_legend: see picture_legend.h. */
#include "app/picture_legend.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "app/distortion_scale.h"
#include "app/pixel_font.h"

static const unsigned INK = 0x202020u, GREY = 0x808080u, WHITE = 0xffffffu;

int picture_legend_scale(int width)
{
    int s = width / 300;
    if (s < 2 && width >= 200) s = 2; /* readable on the usual 512-pixel panels */
    return s < 1 ? 1 : s;
}

/* rows: the colour bar (margin, bar, tick, gap, label, margin) and the
 * padding line (label height, margin) */
static int bar_rows(int s) { return 4 * s + 8 * s + 2 * s + 2 * s + 5 * s + 4 * s; }
static int padding_rows(int s) { return 5 * s + 4 * s; }

int picture_legend_strip_height(int width, int energy, double padding)
{
    int s = picture_legend_scale(width), h = 0;
    if (energy) h += bar_rows(s);
    if (padding > 0.0) h += (energy ? 0 : 4 * s) + padding_rows(s);
    return h;
}

static void colour_bar(unsigned char *px, int width, int height, int ch, int y0, int s)
{
    int x0 = 4 * s + pixel_font_width("E", s) + 3 * s;
    int x1 = width - 4 * s - pixel_font_width("16", s) / 2; /* one past the bar */
    if (x1 - x0 < 2) return;
    int ybar = y0 + 4 * s, hbar = 8 * s;
    pixel_font_draw(px, width, height, ch, 4 * s, ybar + (hbar - 5 * s) / 2, "E", s, INK);
    for (int x = x0; x < x1; x++) {
        double t = (double)(x - x0) / (double)(x1 - x0 - 1);
        pixel_fill_rect(px, width, height, ch, x, ybar, 1, hbar, distortion_scale_colour_at(t));
    }
    int last_end = -1;
    for (int k = 0; k < DISTORTION_SCALE_TICKS; k++) {
        double e = distortion_scale_ticks[k];
        int x = x0 + (int)lround(distortion_scale_t(e) * (x1 - x0 - 1));
        pixel_fill_rect(px, width, height, ch, x - s / 2, ybar + hbar, s, 2 * s, INK);
        char label[16];
        snprintf(label, sizeof label, "%g", e);
        int w = pixel_font_width(label, s), lx = x - w / 2;
        if (lx <= last_end + 2 * s) continue; /* would touch the previous label */
        pixel_font_draw(px, width, height, ch, lx, ybar + hbar + 4 * s, label, s, INK);
        last_end = lx + w;
    }
}

void picture_legend_strip(unsigned char *px, int width, int height, int channels, int y0,
                          int energy, double padding_pixels)
{
    int s = picture_legend_scale(width);
    pixel_fill_rect(px, width, height, channels, 0, y0, width, height - y0, WHITE);
    int y = y0;
    if (energy) {
        colour_bar(px, width, height, channels, y, s);
        y += bar_rows(s);
    } else {
        y += 4 * s;
    }
    if (padding_pixels > 0.0) {
        pixel_font_draw(px, width, height, channels, 4 * s, y, "PADDING", s, INK);
        int x = 4 * s + pixel_font_width("PADDING", s) + 3 * s;
        int len = (int)lround(padding_pixels);
        if (len < 1) len = 1;
        /* the length between two end ticks, on the label's middle row */
        pixel_fill_rect(px, width, height, channels, x, y, 1, 5 * s, INK);
        pixel_fill_rect(px, width, height, channels, x + len + 1, y, 1, 5 * s, INK);
        pixel_fill_rect(px, width, height, channels, x + 1, y + 2 * s, len, s, INK);
    }
}

void picture_legend_frame(unsigned char *px, int width, int height, int channels, int x, int y,
                          int w, int h)
{
    pixel_fill_rect(px, width, height, channels, x, y, w, 1, GREY);
    pixel_fill_rect(px, width, height, channels, x, y + h - 1, w, 1, GREY);
    pixel_fill_rect(px, width, height, channels, x, y, 1, h, GREY);
    pixel_fill_rect(px, width, height, channels, x + w - 1, y, 1, h, GREY);
}

void picture_legend_caption(unsigned char *px, int width, int height, int channels, int x, int y,
                            int w, const char *text)
{
    int s = picture_legend_scale(w);
    int tw = pixel_font_width(text, s), tx = x + (w - tw) / 2;
    pixel_fill_rect(px, width, height, channels, tx - s, y, tw + 2 * s, 7 * s, WHITE);
    pixel_font_draw(px, width, height, channels, tx, y + s, text, s, INK);
}

scaf_status picture_legend_chart_numbers(uv_raster *r, const uv_raster_frame *fr, const double *uv,
                                         int nf, const int *F, const int *chart, scaf_error *err)
{
    int nc = 0;
    for (int f = 0; f < nf; f++)
        if (chart[f] + 1 > nc) nc = chart[f] + 1;
    if (nc == 0) return SCAF_OK;
    int *best = malloc(sizeof(int) * (size_t)nc);
    double *area = malloc(sizeof(double) * (size_t)nc);
    double *box = malloc(sizeof(double) * 4 * (size_t)nc); /* x0 y0 x1 y1 in pixels */
    if (!best || !area || !box) {
        free(best);
        free(area);
        free(box);
        return err_nomem(err, "chart numbers");
    }
    for (int c = 0; c < nc; c++) {
        best[c] = -1;
        area[c] = -1.0;
        box[4 * c] = box[4 * c + 1] = INFINITY;
        box[4 * c + 2] = box[4 * c + 3] = -INFINITY;
    }
    for (int f = 0; f < nf; f++) {
        int c = chart[f];
        if (c < 0) continue;
        const double *p[3];
        for (int j = 0; j < 3; j++) {
            p[j] = uv + 2 * (size_t)F[3 * f + j];
            double x = fr->ox + (p[j][0] - fr->u0) * fr->scale;
            double y = fr->oy + (fr->v1 - p[j][1]) * fr->scale;
            box[4 * c] = fmin(box[4 * c], x);
            box[4 * c + 1] = fmin(box[4 * c + 1], y);
            box[4 * c + 2] = fmax(box[4 * c + 2], x);
            box[4 * c + 3] = fmax(box[4 * c + 3], y);
        }
        double a = fabs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                        (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
        if (a > area[c]) area[c] = a, best[c] = f;
    }
    int s = picture_legend_scale(r->width);
    for (int c = 0; c < nc; c++) {
        if (best[c] < 0) continue;
        char label[16];
        snprintf(label, sizeof label, "%d", c);
        int w = pixel_font_width(label, s), h = pixel_font_height(s);
        if (w + 2 * s > box[4 * c + 2] - box[4 * c] || h + 2 * s > box[4 * c + 3] - box[4 * c + 1])
            continue; /* the chart is too small on the picture */
        double cx = 0, cy = 0;
        for (int j = 0; j < 3; j++) {
            const double *p = uv + 2 * (size_t)F[3 * best[c] + j];
            cx += (fr->ox + (p[0] - fr->u0) * fr->scale) / 3.0;
            cy += (fr->oy + (fr->v1 - p[1]) * fr->scale) / 3.0;
        }
        int x = (int)lround(cx) - w / 2, y = (int)lround(cy) - h / 2;
        pixel_fill_rect(r->rgba, r->width, r->height, 4, x - s, y - s, w + 2 * s, h + 2 * s, WHITE);
        pixel_font_draw(r->rgba, r->width, r->height, 4, x, y, label, s, INK);
    }
    free(best);
    free(area);
    free(box);
    return SCAF_OK;
}
