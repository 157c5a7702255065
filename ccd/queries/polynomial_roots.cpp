#include <ccd/queries/polynomial_roots.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <algorithm>
#include <gsl/gsl_poly.h>

namespace ccd {
namespace {

// Inserts x into the sorted breakpoint list (strictly inside (lo, hi), no duplicates).
void add_break(MonotoneSplit& s, double x) {
  if (!(x > s.x[0] && x < s.x[s.count - 1]) || s.count >= MonotoneSplit::capacity) return;
  int i = s.count - 1;  // hi stays last
  while (i > 1 && s.x[i - 1] > x) --i;
  if (s.x[i - 1] == x) return;
  for (int k = s.count; k > i; --k) s.x[k] = s.x[k - 1];
  s.x[i] = x;
  ++s.count;
}

// Sign-changing roots of q (degree <= 3) inside (lo, hi), in increasing order, plus exact
// zeros of q at q's own breakpoints. Written into `roots`, returns how many.
int critical_points(const Polynomial& q, double lo, double hi, std::array<double, 3>& roots) {
  const int d = q.degree();
  int n = 0;
  if (d == 0) return 0;
  if (d == 1) {
    const double x = -q.c[0] / q.c[1];
    if (x > lo && x < hi) roots[n++] = x;
    return n;
  }
  if (d == 2) {
    double r0 = 0.0, r1 = 0.0;
    const int k = gsl_poly_solve_quadratic(q.c[2], q.c[1], q.c[0], &r0, &r1);
    // A double root (k == 2, r0 == r1) does not change sign: not an extremum of p, but a
    // harmless extra breakpoint.
    if (k >= 1 && r0 > lo && r0 < hi) roots[n++] = r0;
    if (k == 2 && r1 != r0 && r1 > lo && r1 < hi) roots[n++] = r1;
    return n;
  }
  // d == 3: split q at the roots of q' (quadratic), then refine each sign change.
  MonotoneSplit s;
  s.x[0] = lo;
  s.x[1] = hi;
  s.count = 2;
  std::array<double, 3> inner{};
  const int ni = critical_points(q.derivative(), lo, hi, inner);
  for (int i = 0; i < ni; ++i) add_break(s, inner[i]);
  // Seeds from GSL's closed-form cubic (x^3 + a x^2 + b x + c), polished below.
  double g[3] = {0.0, 0.0, 0.0};
  const int ng = gsl_poly_solve_cubic(q.c[2] / q.c[3], q.c[1] / q.c[3], q.c[0] / q.c[3], &g[0], &g[1], &g[2]);
  const Polynomial dq = q.derivative();
  auto f = [&](double x, double* df) {
    *df = dq(x);
    return q(x);
  };
  for (int i = 0; i < s.count; ++i) s.v[i] = q(s.x[i]);
  for (int i = 0; i + 1 < s.count; ++i) {
    const double a = s.x[i], b = s.x[i + 1];
    const double fa = s.v[i], fb = s.v[i + 1];
    if (i > 0 && fa == 0.0 && n < 3) roots[n++] = a;  // exact zero at an inner breakpoint
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
      double guess = std::numeric_limits<double>::quiet_NaN();
      for (int k = 0; k < ng; ++k)
        if (g[k] > a && g[k] < b) guess = g[k];
      if (n < 3) roots[n++] = refine_sign_change(f, a, b, fa <= 0.0, guess);
    }
  }
  std::sort(roots.begin(), roots.begin() + n);
  return n;
}

}  // namespace

double Polynomial::operator()(double x) const { return gsl_poly_eval(c.data(), 5, x); }

double polynomial_rounding_bound(const Polynomial& p, double lo, double hi) {
  const double m = std::max(std::fabs(lo), std::fabs(hi));
  double sum = 0.0, power = 1.0;
  for (int i = 0; i <= 4; ++i) {
    sum += std::fabs(p.c[i]) * power;
    power *= m;
  }
  const int d = std::max(1, p.degree());
  return 2.0 * 2.0 * d * kEps * sum;
}

MonotoneSplit monotone_split(const Polynomial& p, double lo, double hi) {
  MonotoneSplit s;
  s.x[0] = lo;
  s.count = 1;
  if (hi > lo) {
    s.x[1] = hi;
    s.count = 2;
    std::array<double, 3> crit{};
    const int n = critical_points(p.derivative(), lo, hi, crit);
    for (int i = 0; i < n; ++i) add_break(s, crit[i]);
  }
  for (int i = 0; i < s.count; ++i) s.v[i] = p(s.x[i]);
  return s;
}

SublevelSet polynomial_sublevel_set(const Polynomial& p, double lo, double hi, double tol) {
  if (hi < lo) return {};
  const MonotoneSplit s = monotone_split(p, lo, hi);
  const Polynomial dp = p.derivative();
  auto f = [&](double x, double* df) {
    *df = dp(x);
    return p(x);
  };
  return sublevel_set_from_split(s, tol, [&](int i) {
    return refine_sign_change(f, s.x[i], s.x[i + 1], s.v[i] <= 0.0, std::numeric_limits<double>::quiet_NaN());
  });
}

RealRoots polynomial_roots(const Polynomial& p, double lo, double hi, double tol) {
  RealRoots r;
  if (hi < lo || p.degree() == 0) return r;
  const MonotoneSplit s = monotone_split(p, lo, hi);
  const Polynomial dp = p.derivative();
  auto f = [&](double x, double* df) {
    *df = dp(x);
    return p(x);
  };
  auto add = [&r](double x, bool touching) {
    if (r.count > 0 && r.x[r.count - 1] == x) return;
    if (r.count < RealRoots::capacity) {
      r.x[r.count] = x;
      r.touching[r.count] = touching;
      ++r.count;
    }
  };
  const int m = s.count - 1;
  for (int i = 0; i <= m; ++i) {
    const double v = s.v[i];
    const bool local_min = (i == 0 || s.v[i - 1] >= v) && (i == m || s.v[i + 1] >= v);
    const bool local_max = (i == 0 || s.v[i - 1] <= v) && (i == m || s.v[i + 1] <= v);
    // An extremum within tol of zero (both neighbours on the same side) touches zero.
    if (std::fabs(v) <= tol && (local_min || local_max) && i > 0 && i < m &&
        ((s.v[i - 1] > 0.0 && s.v[i + 1] > 0.0) || (s.v[i - 1] < 0.0 && s.v[i + 1] < 0.0))) {
      add(s.x[i], true);
    } else if (v == 0.0 || (std::fabs(v) <= tol && (i == 0 || i == m) && (local_min || local_max))) {
      add(s.x[i], false);
    }
    if (i < m) {
      const double fa = s.v[i], fb = s.v[i + 1];
      if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
        // Skip a crossing that belongs to a snapped touching extremum.
        const bool snapped_a = r.count > 0 && r.x[r.count - 1] == s.x[i] && r.touching[r.count - 1];
        const bool snapped_b = i + 1 < m && std::fabs(fb) <= tol && s.v[i] * s.v[i + 2] > 0.0 &&
                               (s.v[i + 2] > 0.0) == (fa > 0.0);
        if (!snapped_a && !snapped_b) {
          const double a = s.x[i], b = s.x[i + 1];
          add(refine_sign_change(f, a, b, fa <= 0.0, std::numeric_limits<double>::quiet_NaN()), false);
        }
      }
    }
  }
  return r;
}

}  // namespace ccd
