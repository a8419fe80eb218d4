/* opt/area_matched_energy: see area_matched_energy.h. */
#include "opt/area_matched_energy.h"

#include <math.h>

/* One face's 3D edges in its own plane (x1 = (l1, 0), x2 = (a, b)) and its
 * UV edges: the Jacobian J = U X^-1 has ||J||_F^2 and det J; for a 2 by 2
 * matrix ||J^-1||_F^2 = ||J||_F^2 / det(J)^2. */
typedef struct face_terms {
    double area3, area2, frob2;
} face_terms;

static face_terms face_of(const double *p0, const double *p1, const double *p2, const double *u0,
                          const double *u1, const double *u2)
{
    double e1[3], e2[3], c[3];
    for (int k = 0; k < 3; k++) e1[k] = p1[k] - p0[k], e2[k] = p2[k] - p0[k];
    c[0] = e1[1] * e2[2] - e1[2] * e2[1];
    c[1] = e1[2] * e2[0] - e1[0] * e2[2];
    c[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    double twice3 = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    face_terms t = {0.5 * twice3, 0.0, 0.0};
    if (!(l1 > 0.0) || !(twice3 > 0.0)) return t;
    double a = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1, b = twice3 / l1;
    double ux1 = u1[0] - u0[0], uy1 = u1[1] - u0[1], ux2 = u2[0] - u0[0], uy2 = u2[1] - u0[1];
    /* X^-1 = [1/l1, -a/(l1 b); 0, 1/b]; J = U X^-1 column by column */
    double j00 = ux1 / l1, j10 = uy1 / l1;
    double j01 = (ux2 - a * j00) / b, j11 = (uy2 - a * j10) / b;
    t.area2 = 0.5 * (ux1 * uy2 - uy1 * ux2);
    t.frob2 = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
    return t;
}

double area_matched_energy(const double *V, const int *F, int nf, const double *UV, const int *FT)
{
    double A3 = 0.0, A2 = 0.0;
    for (int f = 0; f < nf; f++) {
        const int *v = F + 3 * f, *u = FT + 3 * f;
        face_terms t = face_of(V + 3 * v[0], V + 3 * v[1], V + 3 * v[2], UV + 2 * u[0],
                               UV + 2 * u[1], UV + 2 * u[2]);
        if (t.area3 > 0.0 && !(t.area2 > 0.0)) return INFINITY; /* flipped or flat */
        A3 += t.area3, A2 += t.area2;
    }
    if (!(A3 > 0.0)) return NAN;
    if (!(A2 > 0.0)) return INFINITY;
    double s2 = A3 / A2, sum = 0.0;
    for (int f = 0; f < nf; f++) {
        const int *v = F + 3 * f, *u = FT + 3 * f;
        face_terms t = face_of(V + 3 * v[0], V + 3 * v[1], V + 3 * v[2], UV + 2 * u[0],
                               UV + 2 * u[1], UV + 2 * u[2]);
        if (!(t.area3 > 0.0)) continue; /* a zero-area 3D face weighs nothing */
        double det = t.area2 / t.area3; /* det J: UV area over 3D area */
        sum += t.area3 * (s2 * t.frob2 + t.frob2 / (s2 * det * det));
    }
    return sum / A3;
}
