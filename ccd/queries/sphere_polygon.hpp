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
// (m_i = N x e_i the in-plane inward normal of edge i, e_i = V_{i+1} - V_i, N the area
// normal sum_i (V_i - V_0) x (V_{i+1} - V_0): the slab condition is taken squared,
// (N . (c - V_0))^2 <= r^2 |N|^2, so that no square root or unit normal enters). Every
// condition is a polynomial in t of degree <= 4 (c is quadratic). Each is solved like the
// sphere-sphere contact function (ccd/queries/certified_sublevel_set.hpp): located on its
// double-precision polynomial, then decided in double-double (the centre from the
// piece's exact state, the differences of vertices formed exactly) against a certified
// bound on its error, critical points and boundaries polished to adjacent doubles. Each
// feature's set is the intersection of its conditions' sets; the union of the features'
// sets, with overlapping or touching intervals merged, is the answer.
// Guarantee (docs/truth.md, "Body against scenery"): the data are exact (vertices, radius,
// the piece's double-double state); a condition counts as met where its value is within
// its certified band (about 1e-32 of the squared magnitudes), so a tangency is a point
// [t, t] at the double next to the exact time, and a transversal interval end is the last
// double in contact (exact when the true time is a double). Ends equal to u0 or u1 are
// returned exactly. The model's plane is the one through V_0 with normal N (for a polygon
// that scene_io accepted as planar within its tolerance but is not exactly planar, this
// is the polygon's definition).
// Degenerate cases: u1 < u0, r < 0, non-finite input or a polygon with fewer than 3
// vertices or zero area: nothing is appended. A zero-length edge is skipped (its vertices
// still count). `normal` and `offset` are not used; the vertices must run
// counter-clockwise about the area normal, which they do by its definition (either
// winding is accepted). No contact: nothing is appended.
#include <ccd/geometry/vec3.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/queries/contact_interval.hpp>
#include <ccd/scene/scenery.hpp>

#include <vector>

namespace ccd {

/// Appends every maximal contact interval within [u0, u1] (times absolute) of the sphere
/// of radius r centred at p + v (t - t_ref) + a (t - t_ref)^2 / 2 with `poly`.
void sphere_polygon_contacts(const Vec3& p, const Vec3& v, const Vec3& a, double t_ref, double r,
                             const StaticPolygon& poly, double u0, double u1, std::vector<ContactInterval>& out);

/// The same for one trajectory piece with its exact trailing parts (ccd/motion/trajectory.hpp)
/// over [u0, u1] (within the piece): the ground truth's form.
void sphere_polygon_contacts(const Piece& q, const PieceLow& low, double r, const StaticPolygon& poly, double u0,
                             double u1, std::vector<ContactInterval>& out);

}  // namespace ccd
