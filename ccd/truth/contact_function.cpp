#include <ccd/truth/contact_function.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <gsl/gsl_poly.h>
#include <limits>

namespace ccd {
namespace {

constexpr double kU2 = kUnitRoundoff * kUnitRoundoff;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Largest |p| + |v| |s| + |a| s^2 / 2 over the coordinates of piece q at time t.
double magnitude(const Piece& q, double t) {
  const double s = std::fabs(t - q.t0);
  double m = 0.0;
  for (int k = 0; k < 3; ++k)
    m = std::max(m, std::fabs(q.p[k]) + std::fabs(q.v[k]) * s + 0.5 * std::fabs(q.a[k]) * s * s);
  return m;
}
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Error bound of one body's double-double position at t (per coordinate, metres).
double position_error(const Piece& q, const PieceLow& low, double t) {
  double e = 32.0 * kU2 * magnitude(q, t) * (1.0 + 1e-5);
  if (low.edge_error > 0.0 && (t - q.t0 <= low.edge_window || q.t1 - t <= low.edge_window)) e += low.edge_error;
  return e;
}

}  // namespace

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

SublevelSet PairMotion::contact_set(double c0, double c1) const {
  if (!(c1 >= c0)) return {};
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  // Split points of f' (roots of f'', approximately), then the sign changes of f'.
  std::array<double, 4> fs{c0, c1, 0.0, 0.0};
  int nfs = 2;
  if (!shared_acceleration_ && c1 > c0) {
    const Vec3 D0 = qb_->position(c0) - qa_->position(c0);
    const Vec3 Dv = qb_->velocity(c0) - qa_->velocity(c0);
    const Vec3 Da = qb_->a - qa_->a;
    double r0 = 0.0, r1 = 0.0;
    const int k = gsl_poly_solve_quadratic(1.5 * Da.squaredNorm(), 3.0 * Dv.dot(Da), Dv.squaredNorm() + D0.dot(Da),
                                           &r0, &r1);
    for (const double r : {r0, r1}) {
      if (k == 0 || (k == 1 && r == r1 && r0 != r1)) continue;
      const double t = c0 + r;
      if (t > fs[0] && t < c1) fs[nfs++] = t;
    }
    for (int i = 1; i < nfs; ++i)  // insertion sort of at most 4 values
      for (int j = i; j > 0 && fs[j - 1] > fs[j]; --j) std::swap(fs[j - 1], fs[j]);
  }
  auto slope_and_curvature = [this](double x, double* df) {
    const Vec3 dv = qb_->velocity(x) - qa_->velocity(x);
    const Vec3 d = qb_->position(x) - qa_->position(x);
    *df = 2.0 * (dv.squaredNorm() + d.dot(qb_->a - qa_->a));
    return slope(x);
  };
  MonotoneSplit s;
  s.x[0] = c0;
  s.count = 1;
  std::array<bool, MonotoneSplit::capacity> critical{};
  for (int i = 0; i + 1 < nfs; ++i) {
    const double a = fs[i], b = fs[i + 1];
    if (!(b > a)) continue;
    const double sa = slope(a), sb = slope(b);
    double x = kNaN;
    if (i > 0 && sa == 0.0) x = a;
    else if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0))
      x = refine_sign_change(slope_and_curvature, a, b, sa <= 0.0, kNaN);
    if (x > s.x[s.count - 1] && x < c1 && s.count + 1 < MonotoneSplit::capacity) {
      critical[s.count] = true;
      s.x[s.count++] = x;
    }
  }
  if (c1 > c0) s.x[s.count++] = c1;
  // Values and the band.
  double band = 0.0;
  for (int i = 0; i < s.count; ++i) {
    const ContactValue v = value(s.x[i]);
    s.v[i] = v.f;
    double b = v.error;
    if (critical[i]) {
      const double ulp2 = 2.0 * (std::nextafter(std::fabs(s.x[i]), kInfinity) - std::fabs(s.x[i]));
      b += curvature_bound(s.x[i]) * ulp2 * ulp2;
    }
    band = std::max(band, b);
  }
  enum State { Out, In, Touch };
  std::array<State, MonotoneSplit::capacity> st{};
  const int m = s.count - 1;
  for (int i = 0; i <= m; ++i) {
    const double v = s.v[i];
    const bool local_min = (i == 0 || s.v[i - 1] >= v) && (i == m || s.v[i + 1] >= v);
    if (v > band) {
      st[i] = Out;
    } else if (local_min && v >= -band && (i == 0 || s.v[i - 1] > band) && (i == m || s.v[i + 1] > band)) {
      st[i] = Touch;
    } else {
      st[i] = In;
    }
  }
  auto g = [this, band](double x, double* df) {
    *df = slope(x);
    return value(x).f - band;
  };
  SublevelSet out;
  auto emit = [&out](double lo, double hi) {
    if (out.count < SublevelSet::capacity) out.intervals[out.count++] = {lo, hi};
  };
  bool open = false;
  double start = 0.0;
  for (int i = 0; i <= m; ++i) {
    if (st[i] == Touch) emit(s.x[i], s.x[i]);
    if (st[i] == In && !open) {
      open = true;
      start = s.x[i];
    }
    if (i == m) break;
    const bool in_i = st[i] == In, in_j = st[i + 1] == In;
    if (in_i && !in_j) {
      emit(start, refine_sign_change(g, s.x[i], s.x[i + 1], true, kNaN));
      open = false;
    } else if (!in_i && in_j) {
      open = true;
      start = refine_sign_change(g, s.x[i], s.x[i + 1], false, kNaN);
    }
  }
  if (open) emit(start, s.x[m]);
  return out;
}

bool PairMotion::certainly_apart(double c0, double c1) const {
  const double S = c1 - c0;
  const Vec3 D0 = qb_->position(c0) - qa_->position(c0);
  const Vec3 Dv = qb_->velocity(c0) - qa_->velocity(c0);
  const Vec3 Da = qb_->a - qa_->a;
  const double R = radius_sum_.value();
  auto f_at = [&](double s) { return (D0 + Dv * s + Da * (0.5 * s * s)).squaredNorm() - R * R; };
  double fmin;
  if (Da.isZero(0.0)) {
    const double A = Dv.squaredNorm();
    const double s_star = A > 0.0 ? std::clamp(-D0.dot(Dv) / A, 0.0, S) : 0.0;
    fmin = std::min({f_at(0.0), f_at(S), f_at(s_star)});
  } else {
    Polynomial p;
    p.c[4] = 0.25 * Da.squaredNorm();
    p.c[3] = Dv.dot(Da);
    p.c[2] = Dv.squaredNorm() + D0.dot(Da);
    p.c[1] = 2.0 * D0.dot(Dv);
    p.c[0] = D0.squaredNorm() - R * R;
    const MonotoneSplit sp = monotone_split(p, 0.0, S);
    fmin = f_at(0.0);
    for (int i = 0; i < sp.count; ++i) fmin = std::min(fmin, f_at(sp.x[i]));
  }
  const double M = D0.norm() + Dv.norm() * S + 0.5 * Da.norm() * S * S;
  const double P = std::max(magnitude(*qa_, c1), magnitude(*qb_, c1));
  const double edge = la_->edge_error + lb_->edge_error;
  const double band = 128.0 * kEps * (M + R) * (M + R + P) + 4.0 * (M + R) * edge;
  return fmin > band;
}

bool in_contact(const Trajectories& traj, std::uint32_t a, std::size_t ia, std::uint32_t b, std::size_t ib, double t) {
  const Piece& qa = traj.pieces(a)[ia];
  const Piece& qb = traj.pieces(b)[ib];
  const double R = traj.radius(a) + traj.radius(b);
  const Vec3 d = qb.position(t) - qa.position(t);
  const double dn = d.norm();
  const double f = d.squaredNorm() - R * R;
  const double P = std::max(magnitude(qa, t), magnitude(qb, t));
  const double edge = traj.lows(a)[ia].edge_error + traj.lows(b)[ib].edge_error;
  const double band = 64.0 * kEps * (dn + R) * (dn + R + P) + 4.0 * (dn + R) * edge;
  if (f > band) return false;
  if (f < -band) return true;
  const PairMotion m(qa, traj.lows(a)[ia], traj.radius(a), qb, traj.lows(b)[ib], traj.radius(b));
  const ContactValue v = m.value(t);
  return v.f <= v.error;
}

bool in_contact(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double t) {
  return in_contact(traj, a, traj.piece_index(a, t), b, traj.piece_index(b, t), t);
}

}  // namespace ccd
