#pragma once
// Rounding slack shared by the bounds. Every bound is built from doubles (positions,
// chords, face values) that carry rounding errors of a few ulps of the magnitudes
// involved, and a touching contact sits exactly on a bound's surface. So each bound
// inflates its radii, half-widths and boxes by `rounding_slack(magnitude)`, where
// `magnitude` is the largest coordinate magnitude the body's bound involves
// (|p|_inf + r + |v|_inf h + |a| h^2). 64 ulps covers the handful of operations of each
// construction (each adds at most ~1 ulp of `magnitude`) with a wide margin, and it is far
// below any meaningful size (1.4e-14 relative): "conservative" below means conservative
// for contacts that hold up to this slack.
#include <ccd/geometry/vec3.hpp>
#include <ccd/scene/scenery.hpp>

#include <algorithm>
#include <limits>

namespace ccd {

inline constexpr double kBoundSlackUlps = 64.0;

inline double rounding_slack(double magnitude) {
  return kBoundSlackUlps * std::numeric_limits<double>::epsilon() * magnitude;
}

/// The slack of a static test between a point x (a centre or a segment end) and a polygon:
/// the polygon queries (ccd/queries/point_polygon.hpp, segment_polygon.hpp) work relative
/// to the first vertex, so their rounding is a few ulps of |x - v_0| and of the polygon's
/// extent, plus the rounding of x - v_0 itself (an ulp of |x| and |v_0|).
inline double static_rounding_slack(const Vec3& x, const StaticPolygon& polygon) {
  if (polygon.vertices.empty()) return 0.0;
  const Vec3& v0 = polygon.vertices[0];
  double m = (x - v0).cwiseAbs().maxCoeff() + x.cwiseAbs().maxCoeff() + v0.cwiseAbs().maxCoeff();
  for (const Vec3& v : polygon.vertices) m = std::max(m, (v - v0).cwiseAbs().maxCoeff());
  return rounding_slack(m);
}

}  // namespace ccd
