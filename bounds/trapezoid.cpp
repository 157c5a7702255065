#include <bounds/rounding.hpp>
#include <bounds/trapezoid.hpp>
#include <bounds/wall_fold.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ccd {

Trapezoid restrict_trapezoid(const Trapezoid& z, double u0, double u1) {
  if (u0 == z.t0 && u1 == z.t1) return z;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double h = z.t1 - z.t0;
  Trapezoid r;
  r.t0 = u0;
  r.t1 = u1;
  if (!(h > 0.0)) {  // a single instant: the faces do not move
    r.lo0 = r.lo1 = z.lo0.cwiseMin(z.lo1);
    r.hi0 = r.hi1 = z.hi0.cwiseMax(z.hi1);
    return r;
  }
  // Error of the fraction (t - z.t0) / h: the subtraction's rounding (an ulp of the larger
  // time) over h, and the division's.
  const double du = 4.0 * eps * (std::abs(z.t0) + std::abs(z.t1) + std::abs(u0) + std::abs(u1)) / h + 4.0 * eps;
  const double f0 = std::min(1.0, std::max(0.0, (u0 - z.t0) / h));
  const double f1 = std::min(1.0, std::max(0.0, (u1 - z.t0) / h));
  for (int k = 0; k < 3; ++k) {
    const double dlo = z.lo1[k] - z.lo0[k], dhi = z.hi1[k] - z.hi0[k];
    const double mag = std::max({std::abs(z.lo0[k]), std::abs(z.lo1[k]), std::abs(z.hi0[k]), std::abs(z.hi1[k])});
    const double wlo = du * std::abs(dlo) + 4.0 * eps * mag;
    const double whi = du * std::abs(dhi) + 4.0 * eps * mag;
    r.lo0[k] = z.lo0[k] + dlo * f0 - wlo;
    r.lo1[k] = z.lo0[k] + dlo * f1 - wlo;
    r.hi0[k] = z.hi0[k] + dhi * f0 + whi;
    r.hi1[k] = z.hi0[k] + dhi * f1 + whi;
  }
  return r;
}

PairTest trapezoid_sequence_overlap(const Trapezoid* za, int ma, const Trapezoid* zb, int mb) {
  if (ma <= 0 || mb <= 0) return PairTest::disjoint();
  const double lo = std::max(za[0].t0, zb[0].t0);
  const double hi = std::min(za[ma - 1].t1, zb[mb - 1].t1);
  if (lo > hi) return PairTest::disjoint();
  int i = 0, j = 0;
  while (i < ma && za[i].t1 < lo) ++i;
  while (j < mb && zb[j].t1 < lo) ++j;
  while (i < ma && j < mb) {
    const double u0 = std::max({za[i].t0, zb[j].t0, lo});
    const double u1 = std::min({za[i].t1, zb[j].t1, hi});
    if (u0 <= u1) {
      const PairTest o = trapezoid_overlap(restrict_trapezoid(za[i], u0, u1), restrict_trapezoid(zb[j], u0, u1));
      if (o.possible()) return o;
    }
    if (u1 >= hi) break;
    if (za[i].t1 < zb[j].t1) {
      ++i;
    } else if (zb[j].t1 < za[i].t1) {
      ++j;
    } else {
      ++i;
      ++j;
    }
  }
  return PairTest::disjoint();
}

namespace {

constexpr int kMaxFastPieces = 16;

// horn_trapezoids when no axis of any sub-interval folds: each node's centre band
// [c - w, c + w] is computed once and shared by the two sub-intervals that meet there (the
// same operations as the general loop, so the same doubles). False, writing nothing, when
// some node may pass a wall plane, or for more than kMaxFastPieces sub-intervals.
bool unfolded_horn(const BodyState& s, double t0, double t1, double A, const std::optional<WallBox>& walls, int m,
                   double h, double slack, Trapezoid* out) {
  if (m > kMaxFastPieces) return false;
  const double r = s.radius;
  std::array<Vec3, kMaxFastPieces + 1> lo, hi;
  std::array<double, kMaxFastPieces + 1> time;
  lo[0] = s.position.array() - slack;
  hi[0] = s.position.array() + slack;
  time[0] = t0;
  for (int j = 1; j <= m; ++j) {
    const double s_j = j == m ? h : h * j / m;
    const Vec3 c = s.position + s.velocity * s_j;
    const double w = 0.5 * A * s_j * s_j + slack;
    lo[j] = c.array() - w;
    hi[j] = c.array() + w;
    time[j] = j == m ? t1 : t0 + s_j;
  }
  if (walls) {
    for (int k = 0; k < 3; ++k) {
      const double L = walls->min[k] + r;
      const double H = walls->max[k] - r;
      if (!(L <= H)) continue;  // never folds (as in the general loop)
      for (int j = 0; j <= m; ++j)
        if (!(lo[j][k] >= L && hi[j][k] <= H)) return false;
    }
  }
  for (int j = 0; j < m; ++j) {
    Trapezoid& z = out[j];
    z.t0 = time[j];
    z.t1 = time[j + 1];
    z.lo0 = lo[j].array() - r;
    z.hi0 = hi[j].array() + r;
    z.lo1 = lo[j + 1].array() - r;
    z.hi1 = hi[j + 1].array() + r;
  }
  return true;
}

}  // namespace

bool horn_trapezoids(const BodyState& s, double t0, double t1, double A, const std::optional<WallBox>& walls,
                     int m, Trapezoid* out) {
  const double h = t1 - t0;
  const double r = s.radius;
  const double magnitude = s.position.cwiseAbs().maxCoeff() + r + s.velocity.cwiseAbs().maxCoeff() * h + A * h * h;
  const double slack = rounding_slack(magnitude);
  if (unfolded_horn(s, t0, t1, A, walls, m, h, slack, out)) return false;
  bool folded = false;
  // Node j: time t0 + h j / m, free centre p + v s_j, centre half-width A s_j^2 / 2.
  double s_prev = 0.0;
  Vec3 c_prev = s.position;
  double w_prev = slack;
  for (int j = 0; j < m; ++j) {
    const double s_next = j + 1 == m ? h : h * (j + 1) / m;
    const Vec3 c_next = s.position + s.velocity * s_next;
    const double w_next = 0.5 * A * s_next * s_next + slack;
    Trapezoid& z = out[j];
    z.t0 = t0 + s_prev;
    z.t1 = j + 1 == m ? t1 : t0 + s_next;
    for (int k = 0; k < 3; ++k) {
      const double lo0 = c_prev[k] - w_prev, hi0 = c_prev[k] + w_prev;
      const double lo1 = c_next[k] - w_next, hi1 = c_next[k] + w_next;
      if (walls) {
        const double L = walls->min[k] + r;
        const double H = walls->max[k] - r;
        if (L <= H && (std::min(lo0, lo1) < L || std::max(hi0, hi1) > H)) {
          folded = true;
          const Interval f = fold_interval(std::min(lo0, lo1), std::max(hi0, hi1), L, H);
          z.lo0[k] = z.lo1[k] = f.lo - r - slack;
          z.hi0[k] = z.hi1[k] = f.hi + r + slack;
          continue;
        }
      }
      z.lo0[k] = lo0 - r;
      z.hi0[k] = hi0 + r;
      z.lo1[k] = lo1 - r;
      z.hi1[k] = hi1 + r;
    }
    s_prev = s_next;
    c_prev = c_next;
    w_prev = w_next;
  }
  return folded;
}

}  // namespace ccd
