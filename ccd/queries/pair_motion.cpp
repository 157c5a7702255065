#include <ccd/queries/pair_motion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <gsl/gsl_poly.h>
#include <limits>

namespace ccd {
namespace {

constexpr double kU2 = kUnitRoundoff * kUnitRoundoff;
constexpr double kEps = std::numeric_limits<double>::epsilon();

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Error bound of one body's double-double position at t (per coordinate, metres).
double position_error(const Piece& q, const PieceLow& low, double t) {
  double e = 32.0 * kU2 * piece_magnitude(q, t) * (1.0 + 1e-5) + low.start_error +
             low.velocity_error * std::fabs(t - q.t0) * (1.0 + 1e-5);
  if (low.edge_error > 0.0 && (t - q.t0 <= low.edge_window || q.t1 - t <= low.edge_window)) e += low.edge_error;
  return e;
}

}  // namespace

double piece_magnitude(const Piece& q, double t) {
  const double s = std::fabs(t - q.t0);
  double m = 0.0;
  for (int k = 0; k < 3; ++k)
    m = std::max(m, std::fabs(q.p[k]) + std::fabs(q.v[k]) * s + 0.5 * std::fabs(q.a[k]) * s * s);
  return m;
}

PairMotion::PairMotion(const Piece& qa, const PieceLow& la, double ra, const Piece& qb, const PieceLow& lb, double rb)
    : qa_(&qa), qb_(&qb), la_(&la), lb_(&lb), radius_sum_(two_sum(ra, rb)),
      shared_acceleration_(qa.a == qb.a && la.a == lb.a) {}

ContactValue PairMotion::value(double t) const {
  const DdVec3 d = exact_position(*qb_, *lb_, t) - exact_position(*qa_, *la_, t);
  const Dd d2 = dot(d, d);
  const Dd f = d2 - radius_sum_ * radius_sum_;
  const double dn = std::sqrt(std::max(0.0, d2.value())) * (1.0 + kUnitRoundoff * 4.0);
  const double R = radius_sum_.value();
  const double ed = std::sqrt(3.0) * 1.000001 * (position_error(*qa_, *la_, t) + position_error(*qb_, *lb_, t)) +
                    4.0 * kU2 * dn;
  const double fv = f.value();
  const double err = 2.0 * dn * ed + ed * ed + 16.0 * kU2 * (dn * dn + R * R) + 4.0 * kU2 * std::fabs(fv);
  return {fv, err * (1.0 + 1e-6)};
}

double PairMotion::slope(double t) const {
  const DdVec3 d = exact_position(*qb_, *lb_, t) - exact_position(*qa_, *la_, t);
  const DdVec3 dv = exact_velocity(*qb_, *lb_, t) - exact_velocity(*qa_, *la_, t);
  return 2.0 * dot(d, dv).value();
}

double PairMotion::curvature_bound(double t) const {
  const Vec3 d = qb_->position(t) - qa_->position(t);
  const Vec3 dv = qb_->velocity(t) - qa_->velocity(t);
  const Vec3 da = qb_->a - qa_->a;
  return 2.0 * (dv.squaredNorm() + d.norm() * da.norm()) * (1.0 + 1e-6) + 1e-300;
}

namespace {

// The sign change of a monotone predicate on [a, b] (in(a) == in_a, in(b) != in_a),
// narrowed to two adjacent doubles by stepping out from `guess` in doubling ulps and
// then bisecting: a handful of evaluations when the guess is good. Returns the endpoint
// of the final bracket on the side where in() is true.
template <class In>
double polish_sign_change(In&& in, double a, double b, bool in_a, double guess) {
  double lo = a, hi = b;  // lo keeps a's state, hi b's
  double x = (guess > a && guess < b) ? guess : 0.5 * (a + b);
  if (x > lo && x < hi) {
    if (in(x) == in_a) {
      lo = x;
      for (double step = std::nextafter(x, kInfinity) - x;; step *= 2.0) {
        const double y = lo + step;
        if (!(y < hi)) break;
        if (in(y) != in_a) { hi = y; break; }
        lo = y;
      }
    } else {
      hi = x;
      for (double step = x - std::nextafter(x, -kInfinity);; step *= 2.0) {
        const double y = hi - step;
        if (!(y > lo)) break;
        if (in(y) == in_a) { lo = y; break; }
        hi = y;
      }
    }
  }
  while (true) {
    const double m = lo + 0.5 * (hi - lo);
    if (!(m > lo && m < hi)) break;
    if (in(m) == in_a) lo = m; else hi = m;
  }
  return in_a ? lo : hi;
}

}  // namespace

SublevelSet PairMotion::contact_set(double c0, double c1) const {
  if (!(c1 >= c0)) return {};
  const DoubleSplit ds = double_split(c0, c1);
  if (ds.apart) return {};
  // Critical points: the double estimates, polished on the sign of the double-double f'.
  MonotoneSplit s;
  std::array<bool, MonotoneSplit::capacity> critical{};
  s.x[0] = c0;
  s.count = 1;
  const int n = ds.split.count;
  for (int i = 1; i + 1 < n; ++i) {
    const double lo = c0 + 0.5 * (ds.split.x[i - 1] + ds.split.x[i]);
    const double hi = c0 + 0.5 * (ds.split.x[i] + ds.split.x[i + 1]);
    double x = c0 + ds.split.x[i];
    const double sl = slope(lo), sh = slope(hi);
    if (lo < hi && ((sl <= 0.0) != (sh <= 0.0)))
      x = polish_sign_change([this](double y) { return slope(y) <= 0.0; }, lo, hi, sl <= 0.0, x);
    if (x > s.x[s.count - 1] && x < c1) {
      critical[s.count] = true;
      s.x[s.count++] = x;
    }
  }
  if (c1 > c0) s.x[s.count++] = c1;
  // Values and their bands.
  std::array<double, MonotoneSplit::capacity> band{};
  for (int i = 0; i < s.count; ++i) {
    const ContactValue v = value(s.x[i]);
    s.v[i] = v.f;
    band[i] = v.error;
    if (critical[i]) {
      const double ulp2 = 2.0 * (std::nextafter(std::fabs(s.x[i]), kInfinity) - std::fabs(s.x[i]));
      band[i] += curvature_bound(s.x[i]) * ulp2 * ulp2;
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
  // A boundary between an in and an out breakpoint: the double-precision root as the
  // guess, polished on the double-double predicate f <= band.
  auto boundary = [&](int i, bool in_left) {
    auto f_double = [&](double t, double* df) {
      const double u = t - c0;
      const Vec3 d = ds.D0 + ds.Dv * u + ds.Da * (0.5 * u * u);
      *df = 2.0 * d.dot(ds.Dv + ds.Da * u);
      return d.squaredNorm() - ds.R * ds.R;
    };
    double guess = std::numeric_limits<double>::quiet_NaN();
    if (ds.Da.isZero(0.0)) {
      // f = A u^2 + 2 B u + C: the stable roots q / A and C / q, q = -(B + sign(B) sqrt(B^2 - A C)).
      const double A = ds.Dv.squaredNorm(), B = ds.D0.dot(ds.Dv), C = ds.D0.squaredNorm() - ds.R * ds.R;
      const double disc = B * B - A * C;
      if (A > 0.0 && disc >= 0.0) {
        const double q = -(B + std::copysign(std::sqrt(disc), B));
        // Entering (f decreasing: left of the vertex) is the smaller root.
        const double r0 = q != 0.0 ? std::min(q / A, C / q) : -B / A;
        const double r1 = q != 0.0 ? std::max(q / A, C / q) : -B / A;
        guess = c0 + (in_left ? r1 : r0);
      }
    } else {
      guess = refine_sign_change(f_double, s.x[i], s.x[i + 1], in_left, guess);
    }
    return polish_sign_change(
        [&](double y) {
          const ContactValue v = value(y);
          return v.f <= v.error;
        },
        s.x[i], s.x[i + 1], in_left, guess);
  };
  return assemble_sublevel_set(s, st, boundary);
}

PairMotion::DoubleSplit PairMotion::double_split(double c0, double c1) const {
  DoubleSplit r;
  const double S = c1 - c0;
  r.D0 = qb_->position(c0) - qa_->position(c0);
  r.Dv = qb_->velocity(c0) - qa_->velocity(c0);
  r.Da = qb_->a - qa_->a;
  r.R = radius_sum_.value();
  const Vec3 D0 = r.D0, Dv = r.Dv, Da = r.Da;
  const double R = r.R;
  auto f_at = [&](double u) { return (D0 + Dv * u + Da * (0.5 * u * u)).squaredNorm() - R * R; };
  Polynomial p;
  p.c[4] = 0.25 * Da.squaredNorm();
  p.c[3] = Dv.dot(Da);
  p.c[2] = Dv.squaredNorm() + D0.dot(Da);
  p.c[1] = 2.0 * D0.dot(Dv);
  p.c[0] = D0.squaredNorm() - R * R;
  if (Da.isZero(0.0)) {  // quadratic: one critical point in closed form
    const double A = Dv.squaredNorm();
    r.split.x[0] = 0.0;
    r.split.count = 1;
    const double u = A > 0.0 ? -D0.dot(Dv) / A : 0.0;
    if (u > 0.0 && u < S) r.split.x[r.split.count++] = u;
    if (S > 0.0) r.split.x[r.split.count++] = S;
  } else {
    r.split = monotone_split(p, 0.0, S);
  }
  double fmin = f_at(0.0);
  for (int i = 0; i < r.split.count; ++i) fmin = std::min(fmin, f_at(r.split.x[i]));
  const double M = D0.norm() + Dv.norm() * S + 0.5 * Da.norm() * S * S;
  const double P = std::max(piece_magnitude(*qa_, c1), piece_magnitude(*qb_, c1));
  const double edge = la_->edge_error + lb_->edge_error + la_->start_error + lb_->start_error +
                      (la_->velocity_error + lb_->velocity_error) * (c1 - std::min(qa_->t0, qb_->t0));
  const double band = 128.0 * kEps * (M + R) * (M + R + P) + 4.0 * (M + R) * edge;
  r.apart = fmin > band;
  return r;
}

bool PairMotion::certainly_apart(double c0, double c1) const { return double_split(c0, c1).apart; }

}  // namespace ccd
