#pragma once
// Ray vs plane: the parameter t in [0, t_max] at which p(t) = origin + t * direction meets
// the plane {x : normal . x = offset}. The normal need not be unit length.
//
// Units: positions in scene length units, `direction` in length per unit of t; `offset`
// is in length x |normal|. Formula: t = (offset - n.o) / (n.dir).
//
// Tolerances (derived from the rounding error bounds of the dot products):
//   - on-plane origin: |n.o - offset| <= 8 eps (sum_i |n_i o_i| + |offset|), which bounds
//     the rounding error of the computed residual (gamma_4 <= 4.0001 eps, doubled);
//   - parallel: (n.dir)^2 <= tau^2 |n|^2 |dir|^2, tau = ray_plane_parallel_tolerance =
//     16 eps, i.e. |sin(angle between ray and plane)| <= 16 eps. The computed n.dir is
//     within 3.0001 eps |n||dir| of the exact value, so outside the band its sign is right
//     and its relative error is below 1/5.
// Policy, in this order:
//   Degenerate: zero (or underflowing, |n|^2 < DBL_MIN) normal, non-finite inputs,
//               negative or NaN t_max (t_max = +inf is allowed).
//   origin on the plane: direction parallel (or zero) -> InPlane, toi = 0 (the whole ray
//               lies in the plane); otherwise Hit, toi = 0 (touching at t = 0, closed set,
//               whichever way the ray leaves).
//   Degenerate: zero direction with the origin off the plane (the point never moves).
//   Parallel:   direction parallel within tau, origin off the plane: no contact.
//   Miss:       the crossing is behind the origin (t < 0) or after t_max.
//   Hit:        toi = t in [0, t_max].
// Guarantee: not conservative near the bands (decisions are on computed values, with the
// bands above); toi has relative error O(eps (1 + sum|n_i o_i| / |residual|
// + |n||dir| / |n.dir|)), the conditioning of the problem.
// No contact: toi = +inf.
#include <ccd/geometry/vec3.hpp>

namespace ccd {

inline constexpr double ray_plane_parallel_tolerance = 16.0 * 2.220446049250313080847e-16;  // 16 eps
inline constexpr double ray_plane_on_plane_factor = 8.0;  // times eps, see the header comment

enum class RayPlaneStatus { Hit, Miss, Parallel, InPlane, Degenerate };

struct RayPlaneResult {
  RayPlaneStatus status = RayPlaneStatus::Miss;
  /// Hit: t in [0, t_max]; InPlane: 0; otherwise +inf.
  double toi = 0.0;
};

RayPlaneResult ray_plane(const Vec3& origin, const Vec3& direction, const Vec3& normal, double offset,
                         double t_max);

}  // namespace ccd
