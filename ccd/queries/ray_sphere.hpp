#pragma once
// Ray vs solid sphere: the first parameter t in [0, t_max] at which the point
// p(t) = origin + t * direction lies in the closed ball |p - centre| <= radius.
//
// Units: positions and radius in scene length units; `direction` is a velocity (length
// per unit of t), so t is in the caller's time unit (with a unit direction, t is a length).
// With relative motion (origin = centre_a - centre_b, direction = v_a - v_b, radius =
// r_a + r_b) this is the first contact of two linearly moving spheres.
//
// Method (ccd-math §2): m = origin - centre, a = d.d, b = m.d, k = m.m - R^2. The
// discriminant is formed from the distance of the centre from the line,
// D = a (R^2 - |m - (b/a) d|^2), which does not cancel for grazing rays as b^2 - a k
// does. First root: t = k / (-b + sqrt(D)) (the stable "C/q" form of the quadratic,
// free of cancellation when the origin is near the surface).
//
// Tolerance: tol = ray_sphere_tolerance_factor * eps * max_i |m_i| (a length). It bounds
// the rounding error of the computed distances (|m| and the line's distance h from the
// centre are each computed within ~6 eps |m|; see docs/queries.md). Decisions:
//   - origin within tol of the surface: touching at t = 0 -> Hit, toi = 0 (whatever the
//     direction: contact is a closed set, a point touching and leaving still touches);
//   - origin deeper inside than tol: Overlapping, toi = 0;
//   - line passes within tol outside the sphere (h <= R + tol): reported as a grazing Hit
//     at the closest approach; tangency is never decided by D == 0.
// Guarantee: conservative in classification: if the exact (real-number) answer for the
// given doubles is a contact inside [0, t_max) the result is Hit or Overlapping; a
// reported Hit has the line within tol of the sphere. The toi is not guaranteed to be a
// lower bound. The end of the range is decided on the computed toi (a contact exactly
// at t_max may go either way; it is then found at t = 0 of the next range as touching).
// Accuracy of a Hit (outside the tangency band): |toi - t*| |d| <= C eps |m| (1 + R / w),
// w the half chord; near tangency the root is ill-conditioned (sqrt of the band).
// No contact: Miss with toi = +inf and a zero normal.
// Degenerate: direction with a.a below the smallest normal double (zero or underflowing)
// while the origin is outside the ball (the point never moves: no contact); also negative
// or NaN radius, negative or NaN t_max, non-finite inputs or squares that overflow
// (|coordinate| above ~1e154). t_max = +inf is allowed (an unbounded ray).
#include <ccd/geometry/vec3.hpp>
#include <ccd/queries/query_status.hpp>

namespace ccd {

/// tol = factor * eps * max_i |origin_i - centre_i|, see the header comment.
inline constexpr double ray_sphere_tolerance_factor = 16.0;

/// Hit, Overlapping, Miss or Degenerate (ccd/queries/query_status.hpp).
using RaySphereStatus = QueryStatus;

struct RaySphereResult {
  RaySphereStatus status = RaySphereStatus::Miss;
  /// Hit: first contact in [0, t_max]; Overlapping: 0; Miss and Degenerate: +inf.
  double toi = 0.0;
  /// Hit: unit outward sphere normal at the contact point (zero only when the contact
  /// point is the centre, which needs radius <= tol). Otherwise zero.
  Vec3 normal{Vec3::Zero()};
};

RaySphereResult ray_sphere(const Vec3& origin, const Vec3& direction, const Vec3& centre, double radius,
                           double t_max);

}  // namespace ccd
