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
#include <limits>

namespace ccd {

inline constexpr double kBoundSlackUlps = 64.0;

inline double rounding_slack(double magnitude) {
  return kBoundSlackUlps * std::numeric_limits<double>::epsilon() * magnitude;
}

}  // namespace ccd
