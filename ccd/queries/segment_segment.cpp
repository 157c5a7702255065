#include <ccd/queries/segment_segment.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <algorithm>
#include <limits>

namespace ccd {
namespace {

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

}  // namespace

SegmentSegmentResult segment_segment_closest(const Vec3& p1, const Vec3& q1, const Vec3& p2,
                                             const Vec3& q2) {
  const Vec3 d1 = q1 - p1;
  const Vec3 d2 = q2 - p2;
  const Vec3 r = p1 - p2;
  const double a = d1.dot(d1);
  const double e = d2.dot(d2);
  const double c = d1.dot(r);
  const double f = d2.dot(r);
  SegmentSegmentResult out;
  if (a <= 0.0 || e <= 0.0) {
    out.status = SegmentSegmentResult::Status::Degenerate;
    if (a <= 0.0 && e <= 0.0) {
      out.s = out.t = 0.0;
    } else if (a <= 0.0) {
      out.s = 0.0;
      out.t = clamp01(f / e);  // projection of p1 on the second segment
    } else {
      out.t = 0.0;
      out.s = clamp01(-c / a);  // projection of p2 on the first segment
    }
  } else {
    const double b = d1.dot(d2);
    const double denom = a * e - b * b;
    out.status = denom <= 8.0 * kEps * a * e ? SegmentSegmentResult::Status::Parallel
                                              : SegmentSegmentResult::Status::Unique;
    // For fixed t the best s is clamp((b t - c) / a); h(t) = e t - b s(t) - f is g'(t) / 2.
    const auto s_of = [&](double t) { return clamp01((b * t - c) / a); };
    const auto h_of = [&](double t) { return e * t - b * s_of(t) - f; };
    // Kinks of g' in (0, 1): where b t - c reaches 0 or a.
    double knots[4] = {0.0, 1.0, 1.0, 1.0};
    int n = 1;
    if (b != 0.0) {
      const double k0 = c / b;
      const double k1 = (a + c) / b;
      if (k0 > 0.0 && k0 < 1.0) knots[n++] = k0;
      if (k1 > 0.0 && k1 < 1.0) knots[n++] = k1;
      if (n == 3 && knots[1] > knots[2]) std::swap(knots[1], knots[2]);
    }
    knots[n++] = 1.0;
    double t = 1.0;  // g decreasing all the way: t = 1
    double t_lo = knots[0];
    double h_lo = h_of(t_lo);
    if (h_lo >= 0.0) {
      t = t_lo;
    } else {
      for (int i = 1; i < n; ++i) {
        const double t_hi = knots[i];
        const double h_hi = h_of(t_hi);
        if (h_hi >= 0.0) {
          // g' is linear on [t_lo, t_hi] and changes sign: interpolate its zero. The
          // fraction lies in [0, 1] whatever the magnitudes, so near-parallel is safe.
          const double frac = -h_lo / (h_hi - h_lo);
          t = std::clamp(t_lo + frac * (t_hi - t_lo), t_lo, t_hi);
          break;
        }
        t_lo = t_hi;
        h_lo = h_hi;
      }
    }
    out.t = t;
    out.s = s_of(t);
  }
  out.closest1 = p1 + d1 * out.s;
  out.closest2 = p2 + d2 * out.t;
  out.distance_squared = (out.closest1 - out.closest2).squaredNorm();
  return out;
}

}  // namespace ccd
