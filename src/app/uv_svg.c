/* app/uv_svg: SVG picture of a UV layout (see uv_svg.h).
 *
 * Coordinates are mapped to a 1000-pixel-wide view with y flipped (SVG's y
 * points down). Each triangle is one <polygon>; numbers are printed with
 * enough digits for the view, not for round trips.
 */
#include "app/uv_svg.h"

#include <math.h>
#include <stdio.h>

#include "app/distortion_scale.h"
#include "base/atomic_file.h"

unsigned uv_svg_colour(double energy) { return distortion_scale_colour(energy); }

void uv_svg_colour_bar(FILE *o, double x, double y, double width)
{
    enum { STEPS = 64 };
    double x0 = x + 20.0, w = width - 20.0, h = 14.0;
    fprintf(o, "<g id=\"legend\" font-family=\"sans-serif\" font-size=\"11\">\n");
    fprintf(o, "<text x=\"%.1f\" y=\"%.1f\">E</text>\n", x, y + 11.0);
    for (int k = 0; k < STEPS; k++) {
        double t = (k + 0.5) / STEPS;
        fprintf(o,
                "<rect class=\"scale\" x=\"%.2f\" y=\"%.1f\" width=\"%.2f\" height=\"%.1f\" "
                "fill=\"#%06x\" data-energy=\"%.4g\"/>\n",
                x0 + w * k / STEPS, y, w / STEPS + 0.3, h, distortion_scale_colour_at(t),
                distortion_scale_energy(t));
    }
    for (int k = 0; k < DISTORTION_SCALE_TICKS; k++) {
        double e = distortion_scale_ticks[k], tx = x0 + w * distortion_scale_t(e);
        fprintf(o,
                "<line class=\"tick\" x1=\"%.2f\" y1=\"%.1f\" x2=\"%.2f\" y2=\"%.1f\" "
                "stroke=\"#202020\"/>\n<text class=\"tick\" x=\"%.2f\" y=\"%.1f\" "
                "text-anchor=\"middle\">%g</text>\n",
                tx, y + h, tx, y + h + 4.0, tx, y + h + 16.0, e);
    }
    fprintf(o, "</g>\n");
}

static const double *pos(int id, int nuv, const double *uv, const uv_svg_scaffold *s)
{
    return id < nuv ? uv + 2 * (size_t)id : s->extra + 2 * (size_t)(id - nuv);
}

scaf_status uv_svg_write(const char *path, int nuv, const double *uv, int nf, const int *F,
                         const double *energy, const uv_svg_scaffold *scaffold, const char *title,
                         scaf_error *err)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++) {
            const double *p = uv + 2 * (size_t)F[3 * f + j];
            for (int k = 0; k < 2; k++) {
                if (p[k] < lo[k]) lo[k] = p[k];
                if (p[k] > hi[k]) hi[k] = p[k];
            }
        }
    if (scaffold)
        for (int t = 0; t < scaffold->ntri; t++)
            for (int j = 0; j < 3; j++) {
                const double *p = pos(scaffold->T[3 * t + j], nuv, uv, scaffold);
                for (int k = 0; k < 2; k++) {
                    if (p[k] < lo[k]) lo[k] = p[k];
                    if (p[k] > hi[k]) hi[k] = p[k];
                }
            }
    if (!(hi[0] >= lo[0])) lo[0] = lo[1] = 0.0, hi[0] = hi[1] = 1.0;
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    double ext = w > h ? w : h;
    if (!(ext > 0.0)) ext = 1.0;
    double scale = 1000.0 / ext, margin = 20.0;
    double legend = energy ? 50.0 : 0.0; /* the colour bar's rows */
    double W = w * scale + 2 * margin, H = h * scale + 2 * margin + 30.0 + legend;
    if (W < 720.0) W = 720.0; /* room for the title line on tall layouts */

    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = a.f;
    fprintf(o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(o,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 "
            "0 %.0f %.0f\">\n",
            W, H, W, H);
    fprintf(o, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    if (title) {
        fprintf(o, "<text x=\"%.0f\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">",
                margin);
        for (const char *c = title; *c; c++) {
            if (*c == '<') fputs("&lt;", o);
            else if (*c == '>') fputs("&gt;", o);
            else if (*c == '&') fputs("&amp;", o);
            else fputc(*c, o);
        }
        fprintf(o, "</text>\n");
    }
#define X(p) (margin + ((p)[0] - lo[0]) * scale)
#define Y(p) (30.0 + margin + (hi[1] - (p)[1]) * scale)
    if (scaffold && scaffold->ntri > 0) {
        fprintf(o, "<g fill=\"none\" stroke=\"#b0b0b0\" stroke-width=\"0.4\">\n");
        for (int t = 0; t < scaffold->ntri; t++) {
            const double *p0 = pos(scaffold->T[3 * t], nuv, uv, scaffold);
            const double *p1 = pos(scaffold->T[3 * t + 1], nuv, uv, scaffold);
            const double *p2 = pos(scaffold->T[3 * t + 2], nuv, uv, scaffold);
            fprintf(o, "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\"/>\n", X(p0), Y(p0), X(p1),
                    Y(p1), X(p2), Y(p2));
        }
        fprintf(o, "</g>\n");
    }
    fprintf(o, "<g stroke=\"#303030\" stroke-width=\"0.25\" stroke-linejoin=\"round\">\n");
    for (int f = 0; f < nf; f++) {
        const double *p0 = uv + 2 * (size_t)F[3 * f], *p1 = uv + 2 * (size_t)F[3 * f + 1],
                     *p2 = uv + 2 * (size_t)F[3 * f + 2];
        unsigned c = energy ? uv_svg_colour(energy[f]) : 0xcce5ffu;
        fprintf(o, "<polygon fill=\"#%06x\" points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\"/>\n", c, X(p0),
                Y(p0), X(p1), Y(p1), X(p2), Y(p2));
    }
    fprintf(o, "</g>\n");
    if (energy) uv_svg_colour_bar(o, margin, H - legend + 5.0, W - 2 * margin - 20.0);
    fprintf(o, "</svg>\n");
#undef X
#undef Y
    return atomic_commit(&a, err);
}
