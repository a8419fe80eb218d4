/* app/distortion_scale: see distortion_scale.h. */
#include "app/distortion_scale.h"

#include <math.h>

const double distortion_scale_ticks[DISTORTION_SCALE_TICKS] = {4.0, 4.4, 5.0, 6.0, 8.0, 16.0};

double distortion_scale_t(double energy)
{
    if (!isfinite(energy)) return 1.0;
    if (!(energy > 4.0)) return 0.0;
    double x = log2(energy / 4.0) / log2(DISTORTION_SCALE_TOP / 4.0);
    return x >= 1.0 ? 1.0 : sqrt(x);
}

double distortion_scale_energy(double t)
{
    if (!(t > 0.0)) return 4.0;
    if (t > 1.0) t = 1.0;
    return 4.0 * pow(DISTORTION_SCALE_TOP / 4.0, t * t);
}

unsigned distortion_scale_colour_at(double t)
{
    /* red nondecreasing, blue nonincreasing from stop to stop */
    static const double stops[5][3] = {{0.17, 0.27, 0.80},
                                       {0.20, 0.62, 0.74},
                                       {0.45, 0.78, 0.38},
                                       {0.97, 0.85, 0.20},
                                       {0.98, 0.22, 0.13}};
    if (!(t > 0.0)) t = 0.0;
    if (t > 1.0) t = 1.0;
    double x = t * 4.0;
    int i = (int)x;
    if (i > 3) i = 3;
    double s = x - i;
    unsigned rgb = 0;
    for (int k = 0; k < 3; k++) {
        double v = stops[i][k] * (1.0 - s) + stops[i + 1][k] * s;
        long c = lround(v * 255.0);
        rgb = (rgb << 8) | (unsigned)(c > 255 ? 255 : c < 0 ? 0 : c);
    }
    return rgb;
}

unsigned distortion_scale_colour(double energy)
{
    return distortion_scale_colour_at(distortion_scale_t(energy));
}
