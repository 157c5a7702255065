#pragma once
// Contact intervals of a moving sphere with a static convex polygon (ccd/scene/scenery.hpp).
//
// The centre moves as c(t) = p + v s + a s^2 / 2 with s = t - t_ref (one quadratic piece
// of a trajectory; units: the scene's). Contact means dist(c(t), polygon) <= r, the
// polygon taken as a closed, two-sided convex set (face and boundary). The answer is every
// maximal closed interval of [u0, u1] on which the sphere touches, appended to `out`
// sorted by time; a tangent contact (the distance reaches r without going below) is the
// point interval [t, t].
//
// Method (docs/scenery.md): the distance to a convex polygon is the distance to its
// plane while the centre projects inside it, and otherwise the distance to the nearest
// edge segment; the distance to a segment is the distance to its line while the centre
// projects between the ends, and otherwise the distance to the nearer end. So the contact
// set is the union of
//   face:    |n . (c - V_0)| <= r  and  m_i . (c - V_i) >= 0 for every edge i,
//   edge i:  |e_i x (c - V_i)|^2 <= r^2 |e_i|^2  and  0 <= e_i . (c - V_i) <= |e_i|^2,
//   vertex:  |c - V_i|^2 <= r^2,
// (m_i the in-plane inward normal of edge i, e_i = V_{i+1} - V_i). Every condition is a
// polynomial in s of degree <= 4 (c is quadratic), solved by polynomial_sublevel_set
// (ccd/queries/polynomial_roots.hpp) on the whole [u0, u1] with its tangency rules and
// tolerance polynomial_rounding_bound; each feature's set is the intersection of its
// conditions' sets, and the union of the features' sets, with overlapping or touching
// intervals merged, is the answer. Coefficients are formed from c - V_i (the difference
// rounded once), so the answer is as accurate far from the origin as near it.
// Guarantee: exact up to the rounding band of the polynomials (a few ulps of the data's
// magnitudes); a tangency inside that band is reported as a touching point, so a near
// miss by less than the band may be reported as a touch, never a touch as a miss. Interval
// ends are the in-side brackets of polynomial_sublevel_set (a few ulps of the times);
// ends equal to u0 or u1 are returned exactly.
// Degenerate cases: u1 < u0, r < 0, non-finite input or a polygon with fewer than 3
// vertices: nothing is appended. A zero-length edge is skipped (its vertices still
// count). The polygon's `normal` must be the unit normal of its plane (scene_io fills
// it); the vertex order may be either winding. No contact: nothing is appended.
#include <ccd/geometry/vec3.hpp>
#include <ccd/queries/contact_interval.hpp>
#include <ccd/scene/scenery.hpp>

#include <vector>

namespace ccd {

/// Appends every maximal contact interval within [u0, u1] (times absolute) of the sphere
/// of radius r centred at p + v (t - t_ref) + a (t - t_ref)^2 / 2 with `poly`.
void sphere_polygon_contacts(const Vec3& p, const Vec3& v, const Vec3& a, double t_ref, double r,
                             const StaticPolygon& poly, double u0, double u1, std::vector<ContactInterval>& out);

}  // namespace ccd
