#include <ccd/queries/sphere_sphere_contact.hpp>

#include <cmath>

namespace ccd {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Quadratic case: d(s) = D0 + Dv s.
SublevelSet linear_contact(const Vec3& D0, const Vec3& Dv, double R, double S, double tol) {
  const double A = Dv.squaredNorm();
  const double C = D0.squaredNorm() - R * R;
  MonotoneSplit sp;
  sp.x[0] = 0.0;
  sp.v[0] = C;
  sp.count = 1;
  if (A == 0.0) {  // no relative motion: f is constant
    if (S > 0.0) {
      sp.x[1] = S;
      sp.v[1] = C;
      sp.count = 2;
    }
    return sublevel_set_from_split(sp, tol, [](int) { return 0.0; });
  }
  const double B = D0.dot(Dv);
  const double s_star = -B / A;
  const Vec3 perp = D0 + Dv * s_star;  // closest approach on the whole line
  const double h = perp.norm();
  const double f_star = (h - R) * (h + R);
  if (f_star > tol) return {};  // never within the band anywhere on the line
  if (S > 0.0) {
    if (s_star > 0.0 && s_star < S) {
      sp.x[1] = s_star;
      sp.v[1] = f_star;
      sp.count = 2;
    }
    sp.x[sp.count] = S;
    sp.v[sp.count] = (D0 + Dv * S).squaredNorm() - R * R;
    ++sp.count;
  }
  // Stable roots of A s^2 + 2 B s + C with disc = B^2 - A C = A (R^2 - h^2) >= 0.
  const double disc = A * std::max(0.0, -f_star);
  const double q = -(B + std::copysign(std::sqrt(disc), B));
  double r0 = s_star, r1 = s_star;
  if (q != 0.0) {
    r0 = q / A;
    r1 = C / q;
    if (r0 > r1) std::swap(r0, r1);
  }
  return sublevel_set_from_split(sp, tol, [&](int i) {
    // Left of the vertex f decreases (the entering root r0), right of it increases.
    const double lo = sp.x[i], hi = sp.x[i + 1];
    const double r = (sp.v[i] > sp.v[i + 1]) ? r0 : r1;
    return std::clamp(r, lo, hi);
  });
}

SublevelSet quartic_contact(const Vec3& D0, const Vec3& Dv, const Vec3& Da, double R, double S, double tol) {
  Polynomial p;
  p.c[4] = 0.25 * Da.squaredNorm();
  p.c[3] = Dv.dot(Da);
  p.c[2] = Dv.squaredNorm() + D0.dot(Da);
  p.c[1] = 2.0 * D0.dot(Dv);
  p.c[0] = D0.squaredNorm() - R * R;
  MonotoneSplit sp = monotone_split(p, 0.0, S);
  // f and f' from the vector d(s): the minimum distance does not cancel.
  auto f = [&](double s, double* df) {
    const Vec3 d = D0 + Dv * s + Da * (0.5 * s * s);
    const Vec3 dd = Dv + Da * s;
    *df = 2.0 * d.dot(dd);
    return (d.squaredNorm() - R * R);
  };
  double unused = 0.0;
  for (int i = 0; i < sp.count; ++i) sp.v[i] = f(sp.x[i], &unused);
  return sublevel_set_from_split(sp, tol, [&](int i) {
    return refine_sign_change(f, sp.x[i], sp.x[i + 1], sp.v[i] <= 0.0, std::numeric_limits<double>::quiet_NaN());
  });
}

bool finite_input(const MovingSphere& a, const MovingSphere& b, double S) {
  return std::isfinite(S) && a.position.allFinite() && a.velocity.allFinite() && a.acceleration.allFinite() &&
         b.position.allFinite() && b.velocity.allFinite() && b.acceleration.allFinite() &&
         std::isfinite(a.radius) && std::isfinite(b.radius);
}

}  // namespace

double contact_tolerance(const MovingSphere& a, const MovingSphere& b, double S) {
  const double R = a.radius + b.radius;
  const double M = (b.position - a.position).norm() + (b.velocity - a.velocity).norm() * S +
                   (b.acceleration - a.acceleration).norm() * (0.5 * S * S);
  const double P = std::max(a.position.cwiseAbs().maxCoeff(), b.position.cwiseAbs().maxCoeff());
  return 16.0 * kEps * (M + R) * (M + R + P);
}

SublevelSet sphere_sphere_contact_intervals(const MovingSphere& a, const MovingSphere& b, double S) {
  if (!(S >= 0.0) || !finite_input(a, b, S)) return {};
  const Vec3 D0 = b.position - a.position;
  const Vec3 Dv = b.velocity - a.velocity;
  const Vec3 Da = b.acceleration - a.acceleration;
  const double R = a.radius + b.radius;
  const double tol = contact_tolerance(a, b, S);
  if (Da.isZero(0.0)) return linear_contact(D0, Dv, R, S, tol);
  return quartic_contact(D0, Dv, Da, R, S, tol);
}

SphereSphereContact sphere_sphere_first_contact(const MovingSphere& a, const MovingSphere& b, double S) {
  const SublevelSet set = sphere_sphere_contact_intervals(a, b, S);
  if (set.count == 0) return {};
  const double t = set.intervals[0].lo;
  return {t == 0.0 ? ContactStatus::Overlapping : ContactStatus::Hit, t};
}

}  // namespace ccd
