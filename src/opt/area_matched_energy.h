/* opt/area_matched_energy: the one distortion figure users read.
 *
 * E = sum_f A_f (||s J_f||_F^2 + ||(s J_f)^-1||_F^2) / sum_f A_f, the
 * symmetric Dirichlet energy of the map with its UVs scaled uniformly by s
 * so that their total area equals the surface's (s^2 = sum A_f / sum a_f;
 * A_f 3D area, a_f UV area, J_f the map's Jacobian on face f). 4 at an
 * isometry; the same for a map and any uniform scaling, translation or
 * rotation of it, so the optimizer's layout, the atlas written into the
 * unit square and the editor's view of it all give one number.
 *
 * Why area-matched: the optimizer's own energy is measured at the layout's
 * scale, which the atlas then shrinks into the unit square, so the same
 * map read 4.48 in `scaf atlas`, 17.4 to a checker at the unit square and
 * 5.45 in the editor. Matching the area is what every UV tool's
 * "area-matched" distortion does and needs no optimization.
 *
 * Fails (returns +INFINITY) when a face has zero or negative UV area (not
 * a map whose distortion is finite); NAN when the surface has no area.
 */
#ifndef SCAF_OPT_AREA_MATCHED_ENERGY_H
#define SCAF_OPT_AREA_MATCHED_ENERGY_H

/* V: 3D positions (x, y, z per vertex), F: nf faces into V, UV: 2D
 * positions, FT: nf faces into UV (FT = F when UV has one entry per
 * vertex). Indices are trusted (the caller's mesh is validated). */
double area_matched_energy(const double *V, const int *F, int nf, const double *UV, const int *FT);

#endif
