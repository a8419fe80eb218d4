/* app/inflate: the target of `scaf inflate` — the surface scaled K times
 * about its centroid (area-weighted: the centre of its faces' mass, not
 * moved by how finely a part is meshed) — and the measure of how far it
 * grew (the bounding box's diagonal). The run itself is app/volume_deform.
 */
#ifndef SCAF_APP_INFLATE_H
#define SCAF_APP_INFLATE_H

/* target (nv by 3) = c + K (V - c), c the area-weighted centroid of the
 * faces F (nf by 3) over V (nv by 3); the vertex mean when the area is 0. */
void inflate_target(int nv, const double *V, int nf, const int *F, double K, double *target);

/* The diagonal of the bounding box of V (nv by 3). */
double inflate_bbox_diagonal(int nv, const double *V);

#endif /* SCAF_APP_INFLATE_H */
