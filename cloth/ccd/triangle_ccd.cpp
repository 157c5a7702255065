#include "triangle_ccd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ccd::cloth {
namespace {

// Error bound of a corner value (u = 2^-53 is the unit roundoff; M = max |input|).
// Parameters t, a, b are dyadic with at most 52 fractional bits, so 1 - t, 1 - a - b,
// 1 - a and 1 - b are exact and lie in [-1, 1].
//   x(t) = (1 - t) x0 + t x1: two rounded products and a rounded sum, |x| <= M:
//     error <= 2.01 u M.
//   vertex-face: g = w0 X0 + w1 X1 + w2 X2 with |w0| + |w1| + |w2| <= 3 (a corner of a box
//     may lie outside the triangle): error <= 3 * 2.01 u M (the X's) + 3 u * 3.01 M (three
//     products, two sums) = 15.1 u M; F = X - g, |X - g| <= 4.01 M: + 2.01 u M + 4.01 u M.
//     Total <= 21.2 u M.
//   edge-edge: each side (1 - s) A0 + s A1, weights <= 1 in sum: 2.01 u M + 2.01 u M;
//     difference: + 2.01 u M. Total <= 10.1 u M.
// Both are below 32 u M = 16 eps M. Underflow adds at most 2^-1074 per operation: the
// absolute term 2^-1060 covers far more than the dozen operations of a corner.
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kUnderflowSlack = 0x1p-1060;
constexpr double kMaxMagnitude = 1e300;
constexpr int kMaxDepth = 50;  // parameters keep <= 50 fractional bits

struct Box {
  double lo[3], hi[3];  // t, a, b
  int depth[3];
};

struct Corners {
  double f[8][3];  // corner c = (bit0: t, bit1: a, bit2: b) -> F
};

inline double lerp(double x0, double x1, double t) { return (1.0 - t) * x0 + t * x1; }

template <PrimitivePair Kind>
void evaluate(const LinearQuery& q, const Box& box, Corners& out) {
  for (int it = 0; it < 2; ++it) {
    const double t = it == 0 ? box.lo[0] : box.hi[0];
    double x[4][3];
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) x[i][k] = lerp(q.x[static_cast<std::size_t>(i)][k], q.x[static_cast<std::size_t>(i + 4)][k], t);
    for (int ia = 0; ia < 2; ++ia) {
      const double a = ia == 0 ? box.lo[1] : box.hi[1];
      for (int ib = 0; ib < 2; ++ib) {
        const double b = ib == 0 ? box.lo[2] : box.hi[2];
        double* f = out.f[it | (ia << 1) | (ib << 2)];
        if constexpr (Kind == PrimitivePair::VertexFace) {
          const double w0 = 1.0 - a - b;
          for (int k = 0; k < 3; ++k) f[k] = x[0][k] - ((w0 * x[1][k] + a * x[2][k]) + b * x[3][k]);
        } else {
          for (int k = 0; k < 3; ++k) f[k] = ((1.0 - a) * x[0][k] + a * x[1][k]) - ((1.0 - b) * x[2][k] + b * x[3][k]);
        }
      }
    }
  }
}

template <PrimitivePair Kind>
TriangleCcdResult run(const LinearQuery& q, const TriangleCcdOptions& opt) {
  TriangleCcdResult result;
  double m = 0.0;
  for (const Vec3& p : q.x)
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]) || std::abs(p[k]) > kMaxMagnitude) {
        result.status = QueryStatus::Degenerate;
        result.toi = 0.0;
        return result;
      }
      m = std::max(m, std::abs(p[k]));
    }
  // The query's extent (largest coordinate range) sets the width counted as contact.
  double extent = 0.0;
  for (int k = 0; k < 3; ++k) {
    double lo = q.x[0][k], hi = q.x[0][k];
    for (const Vec3& p : q.x) {
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
    extent = std::max(extent, hi - lo);
  }
  const double err = 16.0 * kEps * m + kUnderflowSlack;
  // Rounded up: thr >= separation + err exactly.
  const double thr = std::nextafter(opt.separation + err, std::numeric_limits<double>::infinity());
  const double width_limit = std::max(opt.tolerance * extent, 4.0 * err);

  thread_local std::vector<Box> stack;
  stack.clear();
  stack.push_back(Box{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}});
  Corners c;
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
      result.toi = first_open_time(box.lo[0]);
      return result;
    }
    ++result.boxes;
    evaluate<Kind>(q, box, c);
    bool excluded = false;
    double width = 0.0;
    for (int k = 0; k < 3 && !excluded; ++k) {
      double lo = c.f[0][k], hi = c.f[0][k];
      for (int i = 1; i < 8; ++i) {
        lo = std::min(lo, c.f[i][k]);
        hi = std::max(hi, c.f[i][k]);
      }
      excluded = lo > thr || hi < -thr;
      width = std::max(width, hi - lo);
    }
    if (excluded) continue;
    // The split direction: the parameter along which the corner values change most.
    int dim = -1;
    double best = -1.0;
    for (int d = 0; d < 3; ++d) {
      if (box.depth[d] >= kMaxDepth) continue;
      double change = 0.0;
      for (int i = 0; i < 8; ++i) {
        if (i & (1 << d)) continue;
        for (int k = 0; k < 3; ++k) change = std::max(change, std::abs(c.f[i | (1 << d)][k] - c.f[i][k]));
      }
      if (change > best) {
        best = change;
        dim = d;
      }
    }
    if (width <= width_limit || dim < 0) {
      result.status = QueryStatus::Hit;
      result.toi = first_open_time(box.lo[0]);
      return result;
    }
    const double mid = 0.5 * (box.lo[dim] + box.hi[dim]);  // exact: dyadic
    Box left = box, right = box;
    left.hi[dim] = mid;
    right.lo[dim] = mid;
    ++left.depth[dim];
    ++right.depth[dim];
    stack.push_back(right);  // the earlier half is examined first
    stack.push_back(left);
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
