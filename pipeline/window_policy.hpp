#pragma once
// How long a body's window of the earliest scheduler is and where it ends
// (pipeline/earliest_scheduler.hpp): dt, or with `reach` the longest dt / 2^k (k <= 10)
// over which the body moves at most the reach length (|v| w + A w^2 / 2, from its state at
// the window's start); with `align` the window ends at the next multiple of its length
// after its start (the fixed steps' grid times), else one length later; never past the
// horizon. The scheduler and the viewer's volumes (experiments/view_volumes.hpp) read it.
#include <ccd/geometry/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace ccd {

struct WindowPolicy {
  double dt = 0.0;
  double horizon = 0.0;
  double acceleration_bound = 0.0;
  double reach_length = 0.0;  ///< reach x the bodies' mean radius; 0: every window is dt long
  bool align = true;

  /// Speed-adapted windows are at least dt / 2^kMaxHalvings long.
  static constexpr int kMaxHalvings = 10;

  /// The window length of a body whose velocity at the window's start is `velocity`.
  double length(const Vec3& velocity) const {
    double w = dt;
    if (!(reach_length > 0.0)) return w;
    const double v = velocity.norm();
    for (int k = 0; k < kMaxHalvings && v * w + 0.5 * acceleration_bound * w * w > reach_length; ++k) w *= 0.5;
    return w;
  }

  /// The end of a window of length `w` that starts at t.
  double end(double w, double t) const {
    double w1 = t + w;
    if (align) {  // the next grid time k w > t (the product, as the fixed steps' times)
      double k = std::floor(t / w) + 1.0;
      while (k > 1.0 && (k - 1.0) * w > t) k -= 1.0;
      while (k * w <= t) k += 1.0;
      w1 = k * w;
    }
    return std::min(w1, horizon);
  }
};

}  // namespace ccd
