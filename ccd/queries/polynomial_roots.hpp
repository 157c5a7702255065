#pragma once
// Robust real root isolation and sublevel sets {x in [lo, hi] : p(x) <= 0} of real
// polynomials of degree <= 4 (the contact function of two moving spheres is a quartic).
//
// Method: split [lo, hi] at the critical points of p (the sign-changing roots of p',
// found recursively: the roots of p'' split p' into monotone parts; quadratics are
// solved in closed form with gsl_poly_solve_quadratic, cubics are seeded with
// gsl_poly_solve_cubic), so p is monotone on every piece. Each sign change on a
// monotone piece is bracketed and refined by safeguarded Newton (bisection whenever a
// Newton step leaves the bracket or does not halve it) to a bracket of a few ulps.
//
// Tangency: a sign-change-only search misses a double root. Here every local minimum
// of p on [lo, hi] (interior critical points and the endpoints) is checked against a
// tolerance `tol` (in the units of p, scale-aware, e.g. polynomial_rounding_bound):
//  - a local minimum with 0 < p <= tol is reported as a point [x, x] (touching);
//  - an interior local minimum with -tol <= p <= 0 whose neighbouring maxima are > 0 is
//    snapped to the point [x, x]: inside the rounding band a double root and a shallow
//    crossing cannot be told apart, and the point is the accurate answer for the former.
// Sublevel-set boundaries are returned on the side where p <= 0 was evaluated, so every
// reported endpoint satisfies the (rounded) predicate. No allocation anywhere.
//
// Degenerate cases: the zero polynomial and constants are handled (whole range or
// empty); hi < lo gives an empty set; hi == lo a single point test.
#include <array>
#include <cmath>
#include <limits>

namespace ccd {

/// p(x) = c[0] + c[1] x + ... + c[4] x^4. Leading zero coefficients are allowed.
struct Polynomial {
  std::array<double, 5> c{};

  /// Index of the highest non-zero coefficient (0 for constants and the zero polynomial).
  int degree() const {
    for (int d = 4; d > 0; --d)
      if (c[d] != 0.0) return d;
    return 0;
  }
  /// Horner evaluation (gsl_poly_eval).
  double operator()(double x) const;
  Polynomial derivative() const {
    Polynomial d;
    for (int i = 1; i <= 4; ++i) d.c[i - 1] = i * c[i];
    return d;
  }
};

/// A closed interval [lo, hi]; lo == hi is a single (touching) point.
struct RootInterval {
  double lo = 0.0;
  double hi = 0.0;
};

/// Up to 3 disjoint closed intervals sorted by lo (a polynomial of degree <= 4 has at
/// most 3 local minima on an interval, and each component holds one).
struct SublevelSet {
  static constexpr int capacity = 3;
  std::array<RootInterval, capacity> intervals{};
  int count = 0;
};

/// Breakpoints lo = x[0] < x[1] < ... < x[count-1] = hi between which p is monotone,
/// and the values of p there. At most 3 interior critical points for degree <= 4.
struct MonotoneSplit {
  static constexpr int capacity = 5;
  std::array<double, capacity> x{};
  std::array<double, capacity> v{};
  int count = 0;
};

/// Distinct real roots in [lo, hi], sorted. `touching` marks roots where p does not
/// change sign (a local minimum or maximum within tol of zero).
struct RealRoots {
  static constexpr int capacity = 4;
  std::array<double, capacity> x{};
  std::array<bool, capacity> touching{};
  int count = 0;
};

/// A bound on the rounding error of evaluating p anywhere in [lo, hi] by Horner's rule:
/// 2 * degree * eps * sum |c_i| m^i with m = max(|lo|, |hi|) (Higham's gamma_{2n}
/// bound, doubled for the coefficients' own rounding). A natural default for `tol`.
double polynomial_rounding_bound(const Polynomial& p, double lo, double hi);

/// Interior critical points of p on [lo, hi] (sign changes of p', plus exact zeros of p'
/// at p'-breakpoints) with lo and hi, and p's values there (breakpoint x-values only;
/// `v` is filled by Horner evaluation).
MonotoneSplit monotone_split(const Polynomial& p, double lo, double hi);

/// {x in [lo, hi] : p(x) <= 0} with the tangency rules above.
SublevelSet polynomial_sublevel_set(const Polynomial& p, double lo, double hi, double tol);

/// All distinct real roots in [lo, hi] (sign changes and touching roots, with tol as above).
/// The zero polynomial has no isolated roots: count 0.
RealRoots polynomial_roots(const Polynomial& p, double lo, double hi, double tol);

// ---- building blocks (templates so that a caller can supply a more accurate f) ------

/// Refines a sign change of a monotone function on [a, b] where `in(a) != in(b)` and
/// in(x) means f(x) <= 0. f_and_df(x, &df) returns f(x) and sets df = f'(x). Returns the
/// final bracket endpoint on the side where f <= 0. `guess` may be NaN.
template <class F>
double refine_sign_change(F&& f_and_df, double a, double b, bool in_a, double guess) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double xtol = eps * 0.5 * (std::fabs(a) + std::fabs(b)) + std::numeric_limits<double>::denorm_min();
  double x = (guess > a && guess < b) ? guess : 0.5 * (a + b);
  double prev_width = b - a;
  for (int iter = 0; iter < 200; ++iter) {
    double df = 0.0;
    const double fx = f_and_df(x, &df);
    if ((fx <= 0.0) == in_a) {
      a = x;
    } else {
      b = x;
    }
    const double width = b - a;
    if (!(width > xtol + eps * std::fabs(a))) break;
    double next = x - fx / df;
    // Safeguard: bisect when Newton leaves the bracket, is undefined, or stalls.
    if (!(next > a && next < b) || width > 0.5 * prev_width) next = 0.5 * (a + b);
    if (next == x) next = 0.5 * (a + b);
    if (next <= a || next >= b) break;  // the bracket is down to adjacent doubles
    prev_width = width;
    x = next;
  }
  return in_a ? a : b;
}

/// What a breakpoint of a monotone split is: out of the set, in it, or an isolated
/// touching point.
enum class SplitState : unsigned char { Out, In, Touch };
using SplitStates = std::array<SplitState, MonotoneSplit::capacity>;

/// The sublevel set from classified breakpoints: a Touch point is [x, x]; between an In
/// and an Out breakpoint, root(i, in_left) returns the in-side boundary of the sign change
/// on segment [x[i], x[i+1]] (in_left: the In breakpoint is x[i]).
template <class Root>
SublevelSet assemble_sublevel_set(const MonotoneSplit& s, const SplitStates& st, Root&& root) {
  SublevelSet out;
  auto emit = [&out](double lo, double hi) {
    if (out.count < SublevelSet::capacity) out.intervals[out.count++] = {lo, hi};
  };
  const int m = s.count - 1;
  bool open = false;
  double start = 0.0;
  for (int i = 0; i <= m; ++i) {
    if (st[i] == SplitState::Touch) emit(s.x[i], s.x[i]);
    if (st[i] == SplitState::In && !open) {
      open = true;
      start = s.x[i];
    }
    if (i == m) break;
    const bool in_i = st[i] == SplitState::In;
    const bool in_j = st[i + 1] == SplitState::In;
    if (in_i && !in_j) {
      emit(start, root(i, true));
      open = false;
    } else if (!in_i && in_j) {
      open = true;
      start = root(i, false);
    }
  }
  if (open) emit(start, s.x[m]);
  return out;
}

/// Assembles the sublevel set from a monotone split whose values are filled in, with the
/// tangency rules above. root(i) returns the in-side boundary of the sign change on
/// segment [x[i], x[i+1]].
template <class Root>
SublevelSet sublevel_set_from_split(const MonotoneSplit& s, double tol, Root&& root) {
  SplitStates st{};
  const int m = s.count - 1;
  for (int i = 0; i <= m; ++i) {
    const double v = s.v[i];
    const bool local_min = (i == 0 || s.v[i - 1] >= v) && (i == m || s.v[i + 1] >= v);
    if (v <= 0.0) {
      const bool snap = local_min && i > 0 && i < m && v >= -tol && s.v[i - 1] > 0.0 && s.v[i + 1] > 0.0;
      st[i] = snap ? SplitState::Touch : SplitState::In;
    } else {
      st[i] = (local_min && v <= tol) ? SplitState::Touch : SplitState::Out;
    }
  }
  return assemble_sublevel_set(s, st, [&](int i, bool) { return root(i); });
}

}  // namespace ccd
