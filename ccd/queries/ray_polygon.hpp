#pragma once
// Ray vs planar convex polygon in 3-D: the parameter t in [0, t_max] at which
// p(t) = origin + t * direction meets the closed polygon given by its vertices in order
// (either winding; the polygon is both-sided).
//
// Units: positions in scene length units, `direction` in length per unit of t.
// Method: the plane hit comes from ray_plane with the polygon's area normal
// n = sum_i (v_i - v_0) x (v_{i+1} - v_0) and the origin taken relative to v_0 (accurate
// far from the coordinate origin). The inside test is done in the ray's frame, not on the
// computed hit point: vertices relative to the origin are projected along the ray onto the
// coordinate plane that drops the axis k of largest |direction_k| (for that projection
// the polygon's largest-|n| axis is replaced by the ray's, which keeps the projection
// well-conditioned whenever the ray is not parallel to the plane). In that plane the ray
// is the point (0, 0); the edge function of edge (a, b) is a_x b_y - a_y b_x, which
// floating point evaluates exactly antisymmetrically in (a, b), and the projected vertex
// coordinates depend on the vertex and the ray only. A zero edge function is resolved by
// a symbolic perturbation of the ray point by (d, d^2), d -> 0+ (half-open rule):
// sign = -sign(b_y - a_y), or sign(b_x - a_x) if that is zero. The point is inside iff
// all non-zero edge signs agree.
// Guarantee (watertightness): polygons that share an edge or a vertex (with identical
// vertex coordinates) and tile a neighbourhood in the ray's projection are hit exactly
// once by a ray through the shared edge or vertex; a closed convex mesh is crossed an
// even number of times. This is why the inside test does not use the per-polygon hit
// point: it is rounded differently for each polygon, so a test on it cannot be exact
// across a shared edge. Planarity is assumed, not checked (a non-planar polygon is
// tested as its projection along the ray against the plane of its area normal).
// Policy: Degenerate for fewer than 3 vertices, a zero area normal (|n|^2 < DBL_MIN),
// zero direction, non-finite inputs or t_max < 0; Parallel when the ray is parallel to
// the plane and off it; Coplanar when the ray lies in the plane (within ray_plane's bands;
// the in-plane segment overlap is not computed); origin on the plane and inside: Hit at
// t = 0. Repeated consecutive vertices (zero-length projected edges) are ignored.
// No contact: Miss (or Parallel) with toi = +inf.
#include <ccd/geometry/vec3.hpp>

#include <span>

namespace ccd {

enum class RayPolygonStatus { Hit, Miss, Parallel, Coplanar, Degenerate };

struct RayPolygonResult {
  RayPolygonStatus status = RayPolygonStatus::Miss;
  /// Hit: t in [0, t_max]; Coplanar: 0; otherwise +inf.
  double toi = 0.0;
};

RayPolygonResult ray_polygon(const Vec3& origin, const Vec3& direction, std::span<const Vec3> vertices,
                             double t_max);

}  // namespace ccd
