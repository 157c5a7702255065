#pragma once
// Distance from a point to a closed segment (a degenerate segment is its point).
#include <ccd/geometry/vec3.hpp>

#include <algorithm>

namespace ccd {

/// |x - closest point of [p0, p1]|, in doubles (the parameter clamped to [0, 1]).
inline double point_segment_distance(const Vec3& x, const Vec3& p0, const Vec3& p1) {
  const Vec3 d = p1 - p0;
  const double dd = d.squaredNorm();
  const double u = dd > 0.0 ? std::clamp((x - p0).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (x - (p0 + d * u)).norm();
}

}  // namespace ccd
