#include "certified_proximity.hpp"

#include <cloth/ccd/parameter_box.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ccd::cloth {
namespace {

using detail::CornerValues;
using detail::kEps;
using detail::kMaxMagnitude;
using detail::kUnderflowSlack;
using Box = detail::ParameterBox;

// A corner proves contact when sum_k (|f_k| + err)^2 <= separation^2 exactly. The computed
// sum carries at most 5 roundings of relative size u = eps / 2 (each |f_k| + err, each
// square, two additions), so its exact value is below sum (1 + 2^-48) plus the underflow
// of the squares; the computed separation^2 is above the exact one by at most u, so
// separation^2 (1 - 2^-48) is a lower bound.
bool corner_within(const double* f, double err, double sep2_low) {
  double s = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double a = std::abs(f[k]) + err;
    s += a * a;
  }
  return s * (1.0 + 0x1p-48) + 0x1p-1000 <= sep2_low;
}

template <PrimitivePair Kind>
ProximityResult run(const LinearQuery& q, double separation, const ProximityOptions& opt) {
  ProximityResult result;
  double m = 0.0, extent = 0.0;
  for (const Vec3& p : q.x)
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]) || std::abs(p[k]) > kMaxMagnitude) return result;  // Undecided
      m = std::max(m, std::abs(p[k]));
    }
  for (int k = 0; k < 3; ++k) {
    double lo = q.x[0][k], hi = lo;
    for (const Vec3& p : q.x) {
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
    extent = std::max(extent, hi - lo);
  }
  const double err = 16.0 * kEps * m + kUnderflowSlack;
  const double thr = std::nextafter(separation + err, std::numeric_limits<double>::infinity());
  const double sep2_low = separation * separation * (1.0 - 0x1p-48);
  const double width_limit = std::max(opt.min_width * extent, 4.0 * err);

  thread_local std::vector<Box> stack;
  stack.clear();
  stack.push_back(Box{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}});
  CornerValues c;
  while (!stack.empty()) {
    const Box box = stack.back();
    stack.pop_back();
    if (Kind == PrimitivePair::VertexFace && box.lo[1] + box.lo[2] > 1.0) continue;  // exact: dyadic
    if (result.boxes == opt.max_boxes) return result;  // Undecided
    ++result.boxes;
    detail::evaluate_corners<Kind>(q, box, c);
    for (int it = 0; it < 2; ++it)
      for (int i = 0; i < c.n; ++i)
        if (corner_within(c.f[it][i], err, sep2_low)) {
          result.decision = Proximity::Within;
          return result;
        }
    double width = 0.0;
    if (detail::excluded_by_component(c, thr, width)) continue;
    if (detail::excluded_along_mean_or_normal(c, separation, err)) continue;
    const int dim = detail::split_dimension(c, box);
    if (width <= width_limit || dim < 0) return result;  // Undecided: a near touch
    detail::push_halves(box, dim, stack);
  }
  result.decision = Proximity::Apart;
  return result;
}

}  // namespace

ProximityResult certified_proximity(PrimitivePair kind, const LinearQuery& q, double separation,
                                    const ProximityOptions& options) {
  if (!(separation >= 0) || !std::isfinite(separation)) return {};
  return kind == PrimitivePair::VertexFace ? run<PrimitivePair::VertexFace>(q, separation, options)
                                           : run<PrimitivePair::EdgeEdge>(q, separation, options);
}

}  // namespace ccd::cloth
