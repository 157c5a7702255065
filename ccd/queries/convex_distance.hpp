#pragma once
// Certified distance between two posed convex proxies (ccd/shape/convex_proxy.hpp) by GJK
// (Gilbert, Johnson and Keerthi), with bounds on both sides:
//
//   lower <= dist(A, B) <= upper      (signed: negative = the shapes overlap)
//
// where A and B are the posed cores conv(points) grown by their radii. The cores are
// worked on in the frame centred on A's centre, so bodies far from the origin lose no
// digits. Per iteration, with v the point of the current simplex closest to the origin
// (a point of the Minkowski difference core(A) - core(B)) and w the support of that
// difference along -v:
//   - upper: |v| (v is a difference of two core points; the grown distance is at most
//     |v| - r_a - r_b);
//   - lower: v.w / |v| (every point x of the difference has v.x >= v.w, the duality
//     gap bound), maximised over the iterations;
//   - when the simplex is a tetrahedron holding the origin, the cores overlap by at least
//     the origin's distance to the tetrahedron's nearest face plane: upper becomes minus
//     that distance.
// Iterations stop when upper - lower <= tolerance, or after max_iterations, or when v
// stops shrinking (rounding); the bounds are valid whenever it stops. Both bounds are
// widened by a rounding allowance: 64 u x (|c_b - c_a| + R_a + R_b), u = 2^-53, R the
// largest |point| of each proxy plus its radius (every computed point, dot product and
// norm is within a few ulps of these magnitudes).
//
// Degenerate input (coincident points, a flat proxy, touching cores): the simplex is
// reduced to the sub-simplex that holds the closest point, so it never inverts a singular
// system; status Failed only if a number is not finite.
#include <ccd/shape/convex_proxy.hpp>

#include <Eigen/Core>
#include <cstdint>

namespace ccd {

/// Where a shape is: its centre (the body frame's origin) and rotation (body to world).
struct ProxyPose {
  Vec3 centre{Vec3::Zero()};
  Eigen::Matrix3d rotation{Eigen::Matrix3d::Identity()};
};

struct DistanceOptions {
  static constexpr double default_tolerance = 1e-9;
  static constexpr int default_max_iterations = 64;
  double tolerance = default_tolerance;  ///< metres: stop when upper - lower <= this
  int max_iterations = default_max_iterations;
  /// Warm start: a guess of the separating direction from A to B (e.g. the previous
  /// answer's `direction`); zero: start along the centres' offset. Changes only the
  /// iterations, never the certificate.
  Vec3 start_direction{Vec3::Zero()};
};

struct ConvexDistance {
  enum class Status : std::uint8_t { Separated, Overlapping, Uncertain, Failed };
  /// Separated: lower > 0; Overlapping: upper < 0; Uncertain: lower <= 0 <= upper (touching
  /// within the bounds' width); Failed: a non-finite number.
  Status status = Status::Failed;
  double lower = 0.0;  ///< metres, certified lower bound on the signed distance
  double upper = 0.0;  ///< metres, certified upper bound
  Vec3 direction{Vec3::Zero()};  ///< unit separating direction from A to B (when lower > 0)
  int iterations = 0;
};

ConvexDistance convex_distance(const ConvexProxy& a, const ProxyPose& pa, const ConvexProxy& b, const ProxyPose& pb,
                               const DistanceOptions& options = {});

}  // namespace ccd
