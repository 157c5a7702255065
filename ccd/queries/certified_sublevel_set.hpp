#pragma once
// The sublevel set {t in [c0, c1] : g(t) <= 0} of a function of time known as a
// polynomial of degree <= 4 in double precision and evaluated accurately (double-double)
// with a certified error bound: the root machinery shared by the sphere-sphere contact
// function (ccd/queries/pair_motion.hpp) and the sphere-polygon conditions
// (ccd/queries/sphere_polygon.hpp). docs/truth.md, "Algorithm", steps 4 to 6.
//
// The caller supplies the approximate monotone split of g (critical points of the double
// polynomial, times relative to c0) and an object G with
//   ContactValue value(double t)       g(t) and a bound on its distance from the exact g(t);
//   double slope(double t)              g'(t), accurately enough for its sign;
//   double curvature_bound(double t)    an upper bound of |g''(t)|;
//   double guess(double a, double b, bool in_left)  a first estimate of the sign change of
//                                       g on [a, b] (NaN: none), in_left: g(a) <= 0.
// Each critical point estimate is polished on the sign of slope() to adjacent doubles;
// g is monotone between them. At each breakpoint the band B is value().error, plus
// |g''| (2 ulp)^2 at an interior critical point (the time quantisation). A point is out
// when g > B; a local minimum with |g| <= B whose neighbouring breakpoints are out is a
// tangency [t, t] (ends of [c0, c1] included); everything else is in. Between an in and
// an out breakpoint the boundary is the last double with g <= its error, found by
// stepping out from guess() in doubling ulps and bisecting. No allocation.
#include <ccd/queries/polynomial_roots.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace ccd {

/// A value rounded to double and a bound on its distance from the exact value.
struct ContactValue {
  double f = 0.0;
  double error = 0.0;
};

/// The sign change of a monotone predicate on [a, b] (in(a) == in_a, in(b) != in_a),
/// narrowed to two adjacent doubles by stepping out from `guess` in doubling ulps and
/// then bisecting: a handful of evaluations when the guess is good. Returns the endpoint
/// of the final bracket on the side where in() is true.
template <class In>
double polish_sign_change(In&& in, double a, double b, bool in_a, double guess) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo = a, hi = b;  // lo keeps a's state, hi b's
  double x = (guess > a && guess < b) ? guess : 0.5 * (a + b);
  if (x > lo && x < hi) {
    if (in(x) == in_a) {
      lo = x;
      for (double step = std::nextafter(x, inf) - x;; step *= 2.0) {
        const double y = lo + step;
        if (!(y < hi)) break;
        if (in(y) != in_a) {
          hi = y;
          break;
        }
        lo = y;
      }
    } else {
      hi = x;
      for (double step = x - std::nextafter(x, -inf);; step *= 2.0) {
        const double y = hi - step;
        if (!(y > lo)) break;
        if (in(y) == in_a) {
          lo = y;
          break;
        }
        hi = y;
      }
    }
  }
  while (true) {
    const double m = lo + 0.5 * (hi - lo);
    if (!(m > lo && m < hi)) break;
    if (in(m) == in_a) {
      lo = m;
    } else {
      hi = m;
    }
  }
  return in_a ? lo : hi;
}

/// {t in [c0, c1] : g(t) <= 0} with the rules above; `approx` is the monotone split of
/// the double-precision polynomial on [0, c1 - c0] (times relative to c0).
template <class G>
SublevelSet certified_sublevel_set(const G& g, const MonotoneSplit& approx, double c0, double c1) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!(c1 >= c0)) return {};
  // Critical points: the double estimates, polished on the sign of the accurate g'.
  MonotoneSplit s;
  std::array<bool, MonotoneSplit::capacity> critical{};
  s.x[0] = c0;
  s.count = 1;
  const int n = approx.count;
  for (int i = 1; i + 1 < n; ++i) {
    const double lo = c0 + 0.5 * (approx.x[i - 1] + approx.x[i]);
    const double hi = c0 + 0.5 * (approx.x[i] + approx.x[i + 1]);
    double x = c0 + approx.x[i];
    const double sl = g.slope(lo), sh = g.slope(hi);
    if (lo < hi && ((sl <= 0.0) != (sh <= 0.0)))
      x = polish_sign_change([&g](double y) { return g.slope(y) <= 0.0; }, lo, hi, sl <= 0.0, x);
    if (x > s.x[s.count - 1] && x < c1) {
      critical[s.count] = true;
      s.x[s.count++] = x;
    }
  }
  if (c1 > c0) s.x[s.count++] = c1;
  // Values and their bands.
  std::array<double, MonotoneSplit::capacity> band{};
  for (int i = 0; i < s.count; ++i) {
    const ContactValue v = g.value(s.x[i]);
    s.v[i] = v.f;
    band[i] = v.error;
    if (critical[i]) {
      const double ulp2 = 2.0 * (std::nextafter(std::fabs(s.x[i]), inf) - std::fabs(s.x[i]));
      band[i] += g.curvature_bound(s.x[i]) * ulp2 * ulp2;
    }
  }
  SplitStates st{};
  const int m = s.count - 1;
  auto out_at = [&](int j) { return s.v[j] > band[j]; };
  for (int i = 0; i <= m; ++i) {
    const double v = s.v[i];
    const bool local_min = (i == 0 || s.v[i - 1] >= v) && (i == m || s.v[i + 1] >= v);
    if (out_at(i)) {
      st[i] = SplitState::Out;
    } else if (local_min && v >= -band[i] && (i == 0 || out_at(i - 1)) && (i == m || out_at(i + 1))) {
      st[i] = SplitState::Touch;
    } else {
      st[i] = SplitState::In;
    }
  }
  // A boundary between an in and an out breakpoint: the caller's estimate, polished on the
  // accurate predicate g <= error.
  auto boundary = [&](int i, bool in_left) {
    return polish_sign_change(
        [&g](double y) {
          const ContactValue v = g.value(y);
          return v.f <= v.error;
        },
        s.x[i], s.x[i + 1], in_left, g.guess(s.x[i], s.x[i + 1], in_left));
  };
  return assemble_sublevel_set(s, st, boundary);
}

}  // namespace ccd
