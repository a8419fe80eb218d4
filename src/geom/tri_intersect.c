/* geom/tri_intersect: exact segment / triangle intersection tests in 3D.
 *
 * Why these tests suffice: two closed convex polygons in space meet iff an
 * edge of one meets the other (the intersection is convex; each of its
 * extreme points lies on the boundary of one of the two). A segment that
 * crosses or touches the plane of a triangle at one point meets the
 * triangle iff the line pq passes on the same side of (or through) the
 * three directed edges, which orient3d(p, q, edge) decides.
 */
#include "geom/tri_intersect.h"

#include "geom/predicates.h"

static int sgn(double x) { return (x > 0) - (x < 0); }

static void drop_axis(int axis, const double p[3], double out[2])
{
    out[0] = p[(axis + 1) % 3];
    out[1] = p[(axis + 2) % 3];
}

double orient2d_dropping(int axis, const double a[3], const double b[3], const double c[3])
{
    double a2[2], b2[2], c2[2];
    drop_axis(axis, a, a2);
    drop_axis(axis, b, b2);
    drop_axis(axis, c, c2);
    return orient2d(a2, b2, c2);
}

int tri3_degenerate(const double a[3], const double b[3], const double c[3])
{
    /* The three projections' orientations are the components of the
     * normal; all zero iff the points are collinear. */
    for (int k = 0; k < 3; k++)
        if (orient2d_dropping(k, a, b, c) != 0) return 0;
    return 1;
}

int tri3_projection_axis(const double a[3], const double b[3], const double c[3])
{
    for (int k = 2; k > 0; k--)
        if (orient2d_dropping(k, a, b, c) != 0) return k;
    return 0;
}

/* r lies on the closed segment pq, given that p, q, r are collinear. */
static int on_segment_2d(const double p[2], const double q[2], const double r[2])
{
    for (int k = 0; k < 2; k++) {
        double lo = p[k] < q[k] ? p[k] : q[k], hi = p[k] < q[k] ? q[k] : p[k];
        if (r[k] < lo || r[k] > hi) return 0;
    }
    return 1;
}

static int seg_seg_2d(const double p[2], const double q[2], const double r[2], const double s[2])
{
    int o1 = sgn(orient2d(p, q, r)), o2 = sgn(orient2d(p, q, s));
    int o3 = sgn(orient2d(r, s, p)), o4 = sgn(orient2d(r, s, q));
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    if (o1 == 0 && on_segment_2d(p, q, r)) return 1;
    if (o2 == 0 && on_segment_2d(p, q, s)) return 1;
    if (o3 == 0 && on_segment_2d(r, s, p)) return 1;
    if (o4 == 0 && on_segment_2d(r, s, q)) return 1;
    return 0;
}

/* p in the closed non-degenerate triangle abc. */
static int point_in_tri_2d(const double p[2], const double a[2], const double b[2],
                           const double c[2])
{
    int s = sgn(orient2d(a, b, c));
    return sgn(orient2d(a, b, p)) != -s && sgn(orient2d(b, c, p)) != -s &&
        sgn(orient2d(c, a, p)) != -s;
}

/* Segment pq lying in the plane of triangle abc. */
static int seg_tri_coplanar(const double p[3], const double q[3], const double a[3],
                            const double b[3], const double c[3])
{
    int axis = tri3_projection_axis(a, b, c);
    double p2[2], q2[2], a2[2], b2[2], c2[2];
    drop_axis(axis, p, p2);
    drop_axis(axis, q, q2);
    drop_axis(axis, a, a2);
    drop_axis(axis, b, b2);
    drop_axis(axis, c, c2);
    return point_in_tri_2d(p2, a2, b2, c2) || point_in_tri_2d(q2, a2, b2, c2) ||
        seg_seg_2d(p2, q2, a2, b2) || seg_seg_2d(p2, q2, b2, c2) || seg_seg_2d(p2, q2, c2, a2);
}

/* Segment pq meeting the plane of triangle t in exactly one point: that
 * point is in t iff the line pq passes every directed edge on one side. */
static int line_meets_tri(const double p[3], const double q[3], const double *const t[3])
{
    int o1 = sgn(orient3d(p, q, t[0], t[1])), o2 = sgn(orient3d(p, q, t[1], t[2])),
        o3 = sgn(orient3d(p, q, t[2], t[0]));
    int has_pos = o1 > 0 || o2 > 0 || o3 > 0, has_neg = o1 < 0 || o2 < 0 || o3 < 0;
    return !(has_pos && has_neg);
}

int seg_tri_intersect(const double p[3], const double q[3], const double a[3], const double b[3],
                      const double c[3])
{
    int sp = sgn(orient3d(a, b, c, p)), sq = sgn(orient3d(a, b, c, q));
    if (sp * sq > 0) return 0;
    if (sp == 0 && sq == 0) return seg_tri_coplanar(p, q, a, b, c);
    const double *const t[3] = {a, b, c};
    return line_meets_tri(p, q, t);
}

/* Signs of orient3d(s, t[k]) for the three vertices of t; 1 when all are
 * nonzero and equal (t strictly on one side of the plane of s). */
static int plane_signs(const double *const s[3], const double *const t[3], int sg[3])
{
    for (int k = 0; k < 3; k++) sg[k] = sgn(orient3d(s[0], s[1], s[2], t[k]));
    return sg[0] != 0 && sg[0] == sg[1] && sg[1] == sg[2];
}

/* Edges of t that reach the plane of s (endpoint signs sg) against s;
 * an edge strictly on one side cannot meet s. */
static int edges_meet(const double *const t[3], const int sg[3], const double *const s[3])
{
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        if (sg[i] * sg[j] > 0) continue;
        if (sg[i] == 0 && sg[j] == 0) {
            if (seg_tri_coplanar(t[i], t[j], s[0], s[1], s[2])) return 1;
        } else if (line_meets_tri(t[i], t[j], s)) {
            return 1;
        }
    }
    return 0;
}

int tri_tri_intersect(const double *const a[3], const double *const b[3])
{
    int sb[3], sa[3];
    if (plane_signs(a, b, sb) || plane_signs(b, a, sa)) return 0;
    return edges_meet(b, sb, a) || edges_meet(a, sa, b);
}
