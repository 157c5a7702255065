#pragma once
// A box that loops around on some axes (`"boundary": "wrap"`, docs/formats.md): the
// periodic images of a body and the image shifts that contact tests, the ground truth and
// the generic image layer of the step pipeline (pipeline/periodic_images.hpp) use.
//
// On a wrapped axis k the scene is periodic with period L_k = max_k - min_k (the exact
// real difference of the two doubles, kept as a double-double): a body and its images at
// p + n L_k (n integer) are the same body. The scene reader requires L_k >= 2 x the
// largest diameter on every wrapped axis, so for two bodies with radii r_a + r_b <= L_k / 2
// at most one image of b per axis lies within contact distance of a at any instant (two
// only at exact tangency on both sides, r_a + r_b == L_k / 2). Reflecting axes have no
// images (shift 0).
#include <ccd/geometry/aabb.hpp>
#include <ccd/geometry/double_double.hpp>
#include <ccd/scene/scene.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace ccd {

/// Image shift in periods per axis (0 on reflecting axes).
using ImageShift = std::array<std::int32_t, 3>;

/// Most periods one box may span on an axis (PeriodicBox::image_range).
inline constexpr int kMaxImageSpan = 1024;

struct PeriodicBox {
  std::array<bool, 3> wrap{false, false, false};
  Vec3 min{Vec3::Zero()};
  Vec3 max{Vec3::Zero()};
  Vec3 period{Vec3::Zero()};      ///< max - min rounded to double (0 on reflecting axes)
  Vec3 period_low{Vec3::Zero()};  ///< exact period = period + period_low

  /// The periodic part of a scene's box; nullopt when no axis wraps.
  static std::optional<PeriodicBox> of(const Scene& scene);

  /// Exact shift n x period on axis k (double-double).
  Dd shift(int k, std::int32_t n) const {
    if (n == 0) return Dd(0.0);
    const double m = static_cast<double>(n);
    return two_prod(m, period[k]) + two_prod(m, period_low[k]);
  }
  /// The shift vector of `s`, rounded to doubles.
  Vec3 offset(const ImageShift& s) const {
    Vec3 o;
    for (int k = 0; k < 3; ++k) o[k] = shift(k, s[k]).value();
    return o;
  }
  /// The image shift that brings b's centre nearest to a's: per wrapped axis the n that
  /// minimises |d + n L| for d = b - a (at |d + n L| == L / 2 both choices are as near).
  ImageShift nearest(const Vec3& a, const Vec3& b) const {
    ImageShift s{0, 0, 0};
    for (std::size_t k = 0; k < 3; ++k)
      if (wrap[k]) {
        const int i = static_cast<int>(k);
        s[k] = static_cast<std::int32_t>(-std::nearbyint((b[i] - a[i]) / period[i]));
      }
    return s;
  }
  /// Range [lo, hi] of shifts n on axis k with [box.lo + n L, box.hi + n L] meeting
  /// [min - slack, max + slack] (slack = 2^-20 L covers the rounding of shifted boxes);
  /// {0, 0} on a reflecting axis.
  std::array<std::int32_t, 2> image_range(const Aabb& box, int k) const {
    if (!wrap[static_cast<std::size_t>(k)]) return {0, 0};
    const double L = period[k];
    const double slack = 0x1p-20 * L;
    const double lo = std::ceil((min[k] - slack - box.hi[k]) / L);
    const double hi = std::floor((max[k] + slack - box.lo[k]) / L);
    // A box over more than kMaxImageSpan periods (a body crossing the box that often in one
    // step) is refused rather than enumerated (or cast out of the int range).
    if (!(hi - lo <= kMaxImageSpan))
      throw std::length_error("a body's box spans more than " + std::to_string(kMaxImageSpan) +
                              " periods of the wrapped box on axis " + std::to_string(k) + " in one step (use a smaller dt)");
    return {static_cast<std::int32_t>(std::min(lo, 0.0)), static_cast<std::int32_t>(std::max(hi, 0.0))};
  }
  /// The shifts n in {-1, 0, +1} on axis k for which the centre box `b` moved by n
  /// periods comes within `reach` of the centre box `a` on that axis (plus a rounding slack
  /// of 1e-9 x (|min| + |max| + L + reach)), in increasing order, written to `out`; returns
  /// how many. On a reflecting axis: just 0. With both centres in [min, max] over the
  /// boxes' time span (positions on a wrapped axis stay there) and reach <= L / 2, no other
  /// shift can bring them within `reach`, and at most one of these does except at exact
  /// tangency on both sides: the candidate image shifts of a pair of bodies with enclosing
  /// radii summing to `reach`.
  int contact_shifts(const Aabb& a, const Aabb& b, double reach, int k, std::array<std::int32_t, 3>& out) const {
    if (!wrap[static_cast<std::size_t>(k)]) {
      out[0] = 0;
      return 1;
    }
    int count = 0;
    const double slack = 1e-9 * (std::fabs(min[k]) + std::fabs(max[k]) + period[k] + reach);
    for (std::int32_t n = -1; n <= 1; ++n) {
      const double off = shift(k, n).value();
      const double gap = std::max(a.lo[k] - (b.hi[k] + off), (b.lo[k] + off) - a.hi[k]);
      if (gap <= reach + slack) out[static_cast<std::size_t>(count++)] = n;
    }
    return count;
  }
  /// Calls f(shift) for every image of `box` that meets the cell [min, max] on every
  /// wrapped axis (see image_range), the original (shift 0) included, first. Two boxes
  /// that overlap after some relative shift n have images (shift m and m + n) that both
  /// meet the cell and overlap each other: so a broad phase over all these images finds
  /// every periodic pair.
  template <class F>
  void for_each_image(const Aabb& box, F&& f) const {
    const auto x = image_range(box, 0), y = image_range(box, 1), z = image_range(box, 2);
    f(ImageShift{0, 0, 0});
    for (std::int32_t i = x[0]; i <= x[1]; ++i)
      for (std::int32_t j = y[0]; j <= y[1]; ++j)
        for (std::int32_t l = z[0]; l <= z[1]; ++l)
          if (i != 0 || j != 0 || l != 0) f(ImageShift{i, j, l});
  }
};

}  // namespace ccd
