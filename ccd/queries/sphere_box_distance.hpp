#pragma once
// Certified signed distance between a ball and a posed box, in closed form: the box is
// the convex hull of its 8 posed corners (as convex_distance sees it,
// ccd/queries/convex_distance.hpp), centre c_b, rotation R (body to world, as evaluated:
// it may be a few ulps from orthogonal), half extents h; the ball has centre c_s and
// radius r. With q = R^T (c_s - c_b) and e_i = |q_i| - h_i:
//
//   g = max_i e_i                      when every e_i <= 0 (the centre inside),
//   g = |(max(e_i, 0))_i|              otherwise,            distance = g - r.
//
// The bounds are the computed value minus and plus an allowance:
//   64 u (|c_s - c_b| + |h| + r) + (|R^T R - I|_F + 32 u) (|c_s - c_b| + |h|),  u = 2^-53,
// the rounding of every step (a few ulps of these magnitudes) and the distance between R
// and the nearest rotation. The allowance is 0, and lower = upper = the exact distance,
// when R is a signed permutation (the identity, a quarter turn about an axis) and every
// subtraction, square, sum and root is verified exact (error-free transformations):
// a dyadic ball touching a box at rest is certified touching (distance exactly 0).
#include <ccd/queries/convex_distance.hpp>

namespace ccd {

/// box.rotation is the box's rotation as evaluated; half_extents > 0.
ConvexDistance sphere_box_distance(const Vec3& centre, double radius, const ProxyPose& box, const Vec3& half_extents);

}  // namespace ccd
