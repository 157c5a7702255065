#pragma once
// The parameter-box search shared by the triangle CCD kernel (triangle_ccd.cpp) and the
// certified proximity decision (certified_proximity.cpp): boxes over (t, a, b), the values of
// F (the vertex-face or edge-edge difference vector, docs/cloth.md) at their corners, and the
// proofs that exclude a box (|F| > separation on all of it).
//
// Error bound of a corner value (u = 2^-53 is the unit roundoff; M = max |input|).
// Parameters t, a, b are dyadic with at most 52 fractional bits, so 1 - t, 1 - a - b,
// 1 - a and 1 - b are exact and lie in [-1, 1].
//   x(t) = (1 - t) x0 + t x1: two rounded products and a rounded sum, |x| <= M:
//     error <= 2.01 u M.
//   vertex-face: g = w0 X0 + w1 X1 + w2 X2 with |w0| + |w1| + |w2| <= 3 (the clipped
//     corners lie in the triangle, where the sum is 1; 3 allows any corner of a box): error
//     <= 3 * 2.01 u M (the X's) + 3 u * 3.01 M (three products, two sums) = 15.1 u M;
//     F = X - g, |X - g| <= 4.01 M: + 2.01 u M + 4.01 u M. Total <= 21.2 u M.
//   edge-edge: each side (1 - s) A0 + s A1, weights <= 1 in sum: 2.01 u M + 2.01 u M;
//     difference: + 2.01 u M. Total <= 10.1 u M.
// Both are below 32 u M = 16 eps M. Underflow adds at most 2^-1074 per operation: the
// absolute term 2^-1060 covers far more than the dozen operations of a corner.
#include <cloth/ccd/linear_query.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ccd::cloth::detail {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kUnderflowSlack = 0x1p-1060;
constexpr double kMaxMagnitude = 1e300;
constexpr int kMaxDepth = 50;  // parameters keep <= 50 fractional bits

struct ParameterBox {
  double lo[3], hi[3];  // t, a, b
  int depth[3];
};

// F at up to 2 x 5 parameter points: both ends of the time interval times the corners of
// the (a, b) region. Vertex-face regions are the box clipped to a + b <= 1 (a polygon of
// up to 5 corners: F is affine in (a, b) for each t, so its range over the region is
// spanned by these corners); edge-edge regions are the 4 box corners.
struct CornerValues {
  int n = 0;                  // points per time
  double f[2][5][3];          // [time][corner][component]
  double da[2][3], db[2][3];  // dF/da, dF/db at both times
};

inline double lerp(double x0, double x1, double t) { return (1.0 - t) * x0 + t * x1; }

// The corners of [a0, a1] x [b0, b1] clipped to a + b <= 1 (Sutherland-Hodgman against
// one half-plane: a rectangle gives at most 5 corners). Crossing points lie on the box's
// axis-parallel edges, at a = 1 - b or b = 1 - a: exact for dyadic a, b. They all lie in
// the closed triangle.
inline int clipped_corners(const ParameterBox& box, double (&ab)[5][2]) {
  const double a0 = box.lo[1], a1 = box.hi[1], b0 = box.lo[2], b1 = box.hi[2];
  const double rect[4][2] = {{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}};
  int n = 0;
  for (int i = 0; i < 4; ++i) {
    const double* p = rect[i];
    const double* q = rect[(i + 1) % 4];
    const bool p_in = p[0] + p[1] <= 1.0, q_in = q[0] + q[1] <= 1.0;
    if (p_in) {
      ab[n][0] = p[0];
      ab[n][1] = p[1];
      ++n;
    }
    if (p_in != q_in) {  // the edge crosses a + b = 1
      if (p[1] == q[1]) {  // horizontal edge
        ab[n][0] = 1.0 - p[1];
        ab[n][1] = p[1];
      } else {  // vertical edge
        ab[n][0] = p[0];
        ab[n][1] = 1.0 - p[0];
      }
      ++n;
    }
  }
  return n;
}

template <PrimitivePair Kind>
void evaluate_corners(const LinearQuery& q, const ParameterBox& box, CornerValues& out) {
  double ab[5][2];
  if constexpr (Kind == PrimitivePair::VertexFace) {
    out.n = clipped_corners(box, ab);
  } else {
    out.n = 4;
    for (int i = 0; i < 4; ++i) {
      ab[i][0] = (i & 1) ? box.hi[1] : box.lo[1];
      ab[i][1] = (i & 2) ? box.hi[2] : box.lo[2];
    }
  }
  for (int it = 0; it < 2; ++it) {
    const double t = it == 0 ? box.lo[0] : box.hi[0];
    double x[4][3];
    for (std::size_t i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) x[i][k] = lerp(q.x[i][k], q.x[i + 4][k], t);
    for (int k = 0; k < 3; ++k) {
      if constexpr (Kind == PrimitivePair::VertexFace) {
        out.da[it][k] = x[2][k] - x[1][k];
        out.db[it][k] = x[3][k] - x[1][k];
      } else {
        out.da[it][k] = x[1][k] - x[0][k];
        out.db[it][k] = x[3][k] - x[2][k];
      }
    }
    for (int c = 0; c < out.n; ++c) {
      const double a = ab[c][0], b = ab[c][1];
      double* f = out.f[it][c];
      if constexpr (Kind == PrimitivePair::VertexFace) {
        const double w0 = 1.0 - a - b;
        for (int k = 0; k < 3; ++k) f[k] = x[0][k] - ((w0 * x[1][k] + a * x[2][k]) + b * x[3][k]);
      } else {
        for (int k = 0; k < 3; ++k) f[k] = ((1.0 - a) * x[0][k] + a * x[1][k]) - ((1.0 - b) * x[2][k] + b * x[3][k]);
      }
    }
  }
}

// A component of F stays above thr (or below -thr) on every corner: the box is excluded
// (F is multilinear, so its range is spanned by the corners). `width` gets the largest
// corner range of the components examined.
inline bool excluded_by_component(const CornerValues& c, double thr, double& width) {
  bool excluded = false;
  width = 0.0;
  for (int k = 0; k < 3 && !excluded; ++k) {
    double lo = c.f[0][0][k], hi = lo;
    for (int it = 0; it < 2; ++it)
      for (int i = 0; i < c.n; ++i) {
        lo = std::min(lo, c.f[it][i][k]);
        hi = std::max(hi, c.f[it][i][k]);
      }
    excluded = lo > thr || hi < -thr;
    width = std::max(width, hi - lo);
  }
  return excluded;
}

// True when n.F > |n| separation at every corner of the box (or n.F < -|n| separation at
// every corner), proved: then |F| > separation on the whole box. Bounds, with n scaled to
// components in [-1, 1]: each corner value has error <= err per component, so the exact n.F
// differs from n.f by at most |n|_1 err; the rounded dot product g = fl(n.f) differs from
// n.f by at most 3u/(1 - 3u) s < 2 eps s, s = sum |n_k f_k| (u = eps / 2; 4 eps s is
// used, which also covers the rounding of s). The computed |n|_2 is rounded up by a
// relative 2^-48 (it is within 4 eps of the exact norm), and the bound as a whole by 2^-40
// (a dozen roundings), plus the underflow slack.
inline bool excluded_along(const double (&dir)[3], const CornerValues& c, double separation, double err) {
  const double scale = std::max({std::abs(dir[0]), std::abs(dir[1]), std::abs(dir[2])});
  if (!(scale > 0) || !std::isfinite(scale)) return false;
  const double n[3] = {dir[0] / scale, dir[1] / scale, dir[2] / scale};
  const double n1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
  const double n2 = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * (1 + 0x1p-48);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, s = 0.0;
  for (int it = 0; it < 2; ++it)
    for (int i = 0; i < c.n; ++i) {
      const double* f = c.f[it][i];
      const double g = (n[0] * f[0] + n[1] * f[1]) + n[2] * f[2];
      lo = std::min(lo, g);
      hi = std::max(hi, g);
      s = std::max(s, std::abs(n[0] * f[0]) + std::abs(n[1] * f[1]) + std::abs(n[2] * f[2]));
    }
  const double bound = (n2 * separation + n1 * err + 4.0 * kEps * s) * (1 + 0x1p-40) + kUnderflowSlack;
  return lo > bound || hi < -bound;
}

// Two more directions n: the mean corner value (F's direction over the box) and da x db
// (the face normal, or the edges' common normal). n.F is multilinear too, so it is
// > |n| separation on the whole box when it is on every corner.
inline bool excluded_along_mean_or_normal(const CornerValues& c, double separation, double err) {
  double mean[3] = {0.0, 0.0, 0.0}, normal[3];
  for (int it = 0; it < 2; ++it)
    for (int i = 0; i < c.n; ++i)
      for (int k = 0; k < 3; ++k) mean[k] += c.f[it][i][k];
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    normal[k] = (c.da[0][k1] * c.db[0][k2] - c.da[0][k2] * c.db[0][k1]) +
                (c.da[1][k1] * c.db[1][k2] - c.da[1][k2] * c.db[1][k1]);
  }
  return excluded_along(mean, c, separation, err) || excluded_along(normal, c, separation, err);
}

// The parameter along which F changes most over the box (an estimate: it only steers the
// search), among those not yet at kMaxDepth; -1 when all are.
inline int split_dimension(const CornerValues& c, const ParameterBox& box) {
  double change[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < c.n; ++i) change[0] = std::max(change[0], std::abs(c.f[1][i][k] - c.f[0][i][k]));
    for (int it = 0; it < 2; ++it) {
      change[1] = std::max(change[1], std::abs(c.da[it][k]) * (box.hi[1] - box.lo[1]));
      change[2] = std::max(change[2], std::abs(c.db[it][k]) * (box.hi[2] - box.lo[2]));
    }
  }
  int dim = -1;
  double best = -1.0;
  for (int d = 0; d < 3; ++d)
    if (box.depth[d] < kMaxDepth && change[d] > best) {
      best = change[d];
      dim = d;
    }
  return dim;
}

// Halves `box` along `dim` (exact: dyadic) and pushes the halves, the earlier (lower) half
// last so that it is examined first.
inline void push_halves(const ParameterBox& box, int dim, std::vector<ParameterBox>& stack) {
  const double mid = 0.5 * (box.lo[dim] + box.hi[dim]);
  ParameterBox left = box, right = box;
  left.hi[dim] = mid;
  right.lo[dim] = mid;
  ++left.depth[dim];
  ++right.depth[dim];
  stack.push_back(right);
  stack.push_back(left);
}

}  // namespace ccd::cloth::detail
