#include <ccd/queries/pair_motion.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <gsl/gsl_poly.h>
#include <limits>

namespace ccd {
namespace {

constexpr double kU2 = kUnitRoundoff * kUnitRoundoff;

}  // namespace

double position_error(const Piece& q, const PieceLow& low, double t) {
  double e = 32.0 * kU2 * piece_magnitude(q, t) * (1.0 + 1e-5) + low.start_error +
             low.velocity_error * std::fabs(t - q.t0) * (1.0 + 1e-5);
  if (low.edge_error > 0.0 && (t - q.t0 <= low.edge_window || q.t1 - t <= low.edge_window)) e += low.edge_error;
  return e;
}

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

// The contact function as certified_sublevel_set sees it: PairMotion's accurate value,
// slope and curvature, and the double-precision root of the relative motion at c0 as the
// first estimate of a boundary (closed form for the quadratic).
struct PairFunction {
  const PairMotion& motion;
  const Vec3& D0;
  const Vec3& Dv;
  const Vec3& Da;
  double R;
  double c0;

  ContactValue value(double t) const { return motion.value(t); }
  double slope(double t) const { return motion.slope(t); }
  double curvature_bound(double t) const { return motion.curvature_bound(t); }
  double guess(double a, double b, bool in_left) const {
    if (Da.isZero(0.0)) {
      // f = A u^2 + 2 B u + C: the stable roots q / A and C / q, q = -(B + sign(B) sqrt(B^2 - A C)).
      const double A = Dv.squaredNorm(), B = D0.dot(Dv), C = D0.squaredNorm() - R * R;
      const double disc = B * B - A * C;
      if (!(A > 0.0 && disc >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
      const double q = -(B + std::copysign(std::sqrt(disc), B));
      // Entering (f decreasing: left of the vertex) is the smaller root.
      const double r0 = q != 0.0 ? std::min(q / A, C / q) : -B / A;
      const double r1 = q != 0.0 ? std::max(q / A, C / q) : -B / A;
      return c0 + (in_left ? r1 : r0);
    }
    auto f_double = [&](double t, double* df) {
      const double u = t - c0;
      const Vec3 d = D0 + Dv * u + Da * (0.5 * u * u);
      *df = 2.0 * d.dot(Dv + Da * u);
      return d.squaredNorm() - R * R;
    };
    return refine_sign_change(f_double, a, b, in_left, std::numeric_limits<double>::quiet_NaN());
  }
};

}  // namespace

SublevelSet PairMotion::contact_set(double c0, double c1) const {
  if (!(c1 >= c0)) return {};
  const DoubleSplit ds = double_split(c0, c1);
  if (ds.apart) return {};
  return certified_sublevel_set(PairFunction{*this, ds.D0, ds.Dv, ds.Da, ds.R, c0}, ds.split, c0, c1);
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
