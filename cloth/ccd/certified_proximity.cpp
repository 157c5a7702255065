#include "certified_proximity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ccd::cloth {
namespace {

// The corner values' error bound is triangle_ccd.cpp's: each component of F at a corner with
// dyadic parameters (at most 52 fractional bits) is within 16 eps M of its exact value, plus
// 2^-1060 for underflow.
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kUnderflowSlack = 0x1p-1060;
constexpr double kMaxMagnitude = 1e300;
constexpr int kMaxDepth = 50;

struct Box {
  double lo[3], hi[3];  // t, a, b
  int depth[3];
};

struct Corners {
  int n = 0;                  // (a, b) points per time
  double f[2][5][3];          // [time][corner][component]
  double da[2][3], db[2][3];  // dF/da, dF/db at both times
};

inline double lerp(double x0, double x1, double t) { return (1.0 - t) * x0 + t * x1; }

// [a0, a1] x [b0, b1] clipped to a + b <= 1: at most 5 corners, exact for dyadic a, b (the
// crossing points are (1 - b, b) or (a, 1 - a)). They all lie in the closed triangle.
int clip(const Box& box, double (&ab)[5][2]) {
  const double rect[4][2] = {{box.lo[1], box.lo[2]}, {box.hi[1], box.lo[2]}, {box.hi[1], box.hi[2]}, {box.lo[1], box.hi[2]}};
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
    if (p_in != q_in) {
      ab[n][0] = p[1] == q[1] ? 1.0 - p[1] : p[0];
      ab[n][1] = p[1] == q[1] ? p[1] : 1.0 - p[0];
      ++n;
    }
  }
  return n;
}

template <PrimitivePair Kind>
void corners(const LinearQuery& q, const Box& box, Corners& out) {
  double ab[5][2];
  if constexpr (Kind == PrimitivePair::VertexFace) {
    out.n = clip(box, ab);
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
      const bool vf = Kind == PrimitivePair::VertexFace;
      out.da[it][k] = vf ? x[2][k] - x[1][k] : x[1][k] - x[0][k];
      out.db[it][k] = vf ? x[3][k] - x[1][k] : x[3][k] - x[2][k];
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

// n.F > |n| separation on every corner (or < -|n| separation): as triangle_ccd.cpp's
// excluded_along, with the same bound.
bool excluded_along(const double (&dir)[3], const Corners& c, double separation, double err) {
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
  Corners c;
  while (!stack.empty()) {
    const Box box = stack.back();
    stack.pop_back();
    if (Kind == PrimitivePair::VertexFace && box.lo[1] + box.lo[2] > 1.0) continue;  // exact: dyadic
    if (result.boxes == opt.max_boxes) return result;  // Undecided
    ++result.boxes;
    corners<Kind>(q, box, c);
    for (int it = 0; it < 2; ++it)
      for (int i = 0; i < c.n; ++i)
        if (corner_within(c.f[it][i], err, sep2_low)) {
          result.decision = Proximity::Within;
          return result;
        }
    bool excluded = false;
    double width = 0.0;
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
    if (excluded) continue;
    double mean[3] = {0.0, 0.0, 0.0}, normal[3];
    for (int it = 0; it < 2; ++it)
      for (int i = 0; i < c.n; ++i)
        for (int k = 0; k < 3; ++k) mean[k] += c.f[it][i][k];
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      normal[k] = (c.da[0][k1] * c.db[0][k2] - c.da[0][k2] * c.db[0][k1]) +
                  (c.da[1][k1] * c.db[1][k2] - c.da[1][k2] * c.db[1][k1]);
    }
    if (excluded_along(mean, c, separation, err) || excluded_along(normal, c, separation, err)) continue;
    // Split along the parameter that changes F most (only steers the search).
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
    if (width <= width_limit || dim < 0) return result;  // Undecided: a near touch
    const double mid = 0.5 * (box.lo[dim] + box.hi[dim]);  // exact: dyadic
    Box left = box, right = box;
    left.hi[dim] = mid;
    right.lo[dim] = mid;
    ++left.depth[dim];
    ++right.depth[dim];
    stack.push_back(right);
    stack.push_back(left);
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
