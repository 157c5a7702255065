#include "triangle_ccd.hpp"

#include <cloth/ccd/hull_direction.hpp>
#include <cloth/ccd/parameter_box.hpp>
#include <cloth/ccd/root_proof.hpp>
#include <cloth/exact/exact_ccd.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ccd::cloth {
namespace {

using detail::CornerValues;
using detail::kEps;
using detail::kMaxMagnitude;
using detail::kUnderflowSlack;
using Box = detail::ParameterBox;

// The query moved so that its bounding box is centred on the origin, and a bound on what
// that move rounded. F is unchanged by a common translation of all eight points, and its
// error bound scales with the largest coordinate, so a query far from the origin is
// searched as precisely as the same query near it.
struct Centred {
  LinearQuery q;
  double magnitude = 0.0;  ///< largest |coordinate| of q
  double shift_error = 0.0;  ///< largest rounding error of one moved coordinate (exact: TwoSum)
  double extent = 0.0;     ///< largest coordinate range over the eight points
};

Centred centred(const LinearQuery& in) {
  Centred c;
  for (int k = 0; k < 3; ++k) {
    double lo = in.x[0][k], hi = lo;
    for (const Vec3& p : in.x) {
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
    c.extent = std::max(c.extent, hi - lo);
    const double mid = 0.5 * lo + 0.5 * hi;  // any value works: only the bound depends on it
    for (std::size_t i = 0; i < 8; ++i) {
      // TwoSum (Knuth): s + e == x - mid exactly.
      const double a = in.x[i][k], b = -mid;
      const double s = a + b, bb = s - a;
      const double e = (a - (s - bb)) + (b - bb);
      c.q.x[i][k] = s;
      c.magnitude = std::max(c.magnitude, std::abs(s));
      c.shift_error = std::max(c.shift_error, std::abs(e));
    }
  }
  return c;
}

enum class StopDecision { Excluded, Contact, ExactContact, ExactMiss };

// Boxes examined before every box also tries the hull's nearest point (cheap tests first:
// random queries, contacts included, are decided within some 300 boxes).
constexpr std::uint32_t kHullAfterBoxes = 1024;

// The box is excluded along the nearest point to the origin of the hull of its corner values.
bool excluded_along_hull(const CornerValues& c, double separation, double err) {
  double points[10][3];
  int n = 0;
  for (int it = 0; it < 2; ++it)
    for (int i = 0; i < c.n; ++i, ++n)
      for (int k = 0; k < 3; ++k) points[n][k] = c.f[it][i][k];
  double dir[3];
  return detail::hull_nearest_point(points, n, dir) && detail::excluded_along(dir, c, separation, err);
}

// A tolerance stop decided (triangle_ccd.hpp): a proved zero of F, the box excluded along
// the hull's nearest point, or the exact reference on the original query.
template <PrimitivePair Kind>
StopDecision decide_stop(const LinearQuery& original, const LinearQuery& q, const detail::ParameterBox& box,
                         const CornerValues& c, double separation, double err, double& t_upper) {
  const double centre[3] = {0.5 * (box.lo[0] + box.hi[0]), 0.5 * (box.lo[1] + box.hi[1]), 0.5 * (box.lo[2] + box.hi[2])};
  if (detail::proves_root(Kind, q, err, centre, t_upper)) return StopDecision::Contact;  // the cheaper test first
  if (excluded_along_hull(c, separation, err)) return StopDecision::Excluded;
  const mpq_class sep(separation);  // exact
  return exact_contact(Kind, to_rational(original), sep * sep) ? StopDecision::ExactContact : StopDecision::ExactMiss;
}

template <PrimitivePair Kind>
TriangleCcdResult run(const LinearQuery& original, const TriangleCcdOptions& opt) {
  TriangleCcdResult result;
  for (const Vec3& p : original.x)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(p[k]) || std::abs(p[k]) > kMaxMagnitude) {
        result.status = QueryStatus::Degenerate;
        result.toi = 0.0;
        return result;
      }
  // The search runs on the centred query. Each corner value of F is an affine combination
  // of the eight points whose weights have absolute sum <= 4 per component (1 for the
  // vertex or 2 for the two edge sides, <= 3 for a face's barycentric weights at any box
  // corner), so the moved points' rounding (<= shift_error each) changes an exact corner
  // value by at most 4 shift_error; the bound is rounded up by a relative 2^-40.
  const Centred cq = centred(original);
  const LinearQuery& q = cq.q;
  const double extent = cq.extent;
  const double err = (16.0 * kEps * cq.magnitude + 4.0 * cq.shift_error) * (1 + 0x1p-40) + kUnderflowSlack;
  // Rounded up: thr >= separation + err exactly.
  const double thr = std::nextafter(opt.separation + err, std::numeric_limits<double>::infinity());
  const double width_limit = std::max(opt.tolerance * extent, 4.0 * err);

  thread_local std::vector<Box> stack;
  stack.clear();
  stack.push_back(Box{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}});
  CornerValues c;
  auto first_open_time = [&](double t) {
    for (const Box& b : stack) t = std::min(t, b.lo[0]);
    return t;
  };
  while (!stack.empty()) {
    const Box box = stack.back();
    stack.pop_back();
    if (Kind == PrimitivePair::VertexFace && box.lo[1] + box.lo[2] > 1.0) continue;  // exact: dyadic
    if (result.boxes == opt.max_boxes) {
      result.status = QueryStatus::Hit;
      result.budget_spent = true;
      result.reason = HitReason::Budget;
      result.toi = first_open_time(box.lo[0]);
      return result;
    }
    ++result.boxes;
    detail::evaluate_corners<Kind>(q, box, c);
    double width = 0.0;
    if (detail::excluded_by_component(c, thr, width)) continue;
    if (detail::excluded_along_mean_or_normal(c, opt.separation, err)) continue;
    // A proved contact: a corner (a point of the primitives' parameter domain) where
    // |F| <= separation although every component may be off by err (|F| <= |f| + sqrt(3)
    // err; |f| as computed is within a relative 4 eps of the exact one: both rounded up).
    // Every earlier time is excluded or still open, so the first open time is a valid toi.
    if (opt.separation > 0) {
      bool touching = false;
      for (int it = 0; it < 2 && !touching; ++it)
        for (int i = 0; i < c.n && !touching; ++i) {
          const double* f = c.f[it][i];
          const double len = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
          touching = (len * (1 + 0x1p-48) + 2.0 * err) * (1 + 0x1p-48) <= opt.separation;
        }
      if (touching) {
        result.status = QueryStatus::Hit;
        result.reason = HitReason::Proved;
        result.toi = first_open_time(box.lo[0]);
        result.toi_upper = box.hi[0];
        return result;
      }
    }
    const int dim = detail::split_dimension(c, box);
    const bool stop = width <= width_limit || dim < 0;  // a tolerance stop
    // A query that needs many boxes (parallel or sliding near misses, where the boxes along
    // a whole curve of near points stay open) tries the hull's nearest point on every box.
    if (!opt.keep_tolerance_stops && !stop && result.boxes > kHullAfterBoxes && excluded_along_hull(c, opt.separation, err))
      continue;
    if (stop) {
      result.reason = HitReason::Tolerance;
      double t_upper = box.hi[0];  // a proved zero's time bound
      if (!opt.keep_tolerance_stops) {
        const StopDecision d = decide_stop<Kind>(original, q, box, c, opt.separation, err, t_upper);
        if (d == StopDecision::Excluded) {
          result.reason = HitReason::None;
          continue;
        }
        result.decided_exactly = d != StopDecision::Contact;
        if (d == StopDecision::ExactMiss) {
          result.reason = HitReason::None;
          break;
        }
        result.reason = d == StopDecision::Contact ? HitReason::Proved : HitReason::Exact;
      }
      result.status = QueryStatus::Hit;
      result.toi = first_open_time(box.lo[0]);
      if (width <= width_limit) result.toi_upper = box.hi[0];
      if (result.reason == HitReason::Proved) result.toi_upper = std::min(result.toi_upper, t_upper);
      return result;
    }
    detail::push_halves(box, dim, stack);
  }
  result.status = QueryStatus::Miss;
  return result;
}

}  // namespace

TriangleCcdResult triangle_ccd(PrimitivePair kind, const LinearQuery& q, const TriangleCcdOptions& options) {
  return kind == PrimitivePair::VertexFace ? run<PrimitivePair::VertexFace>(q, options)
                                           : run<PrimitivePair::EdgeEdge>(q, options);
}

}  // namespace ccd::cloth
