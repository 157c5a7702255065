#include <ccd/queries/ray_sphere.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <Eigen/Geometry>  // cross product

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {

namespace {

RaySphereResult no_contact(RaySphereStatus status) { return {status, kInf, Vec3::Zero()}; }

}  // namespace

RaySphereResult ray_sphere(const Vec3& origin, const Vec3& direction, const Vec3& centre, double radius,
                           double t_max) {
  const Vec3 m = origin - centre;
  const double mm = m.squaredNorm();
  const double a = direction.squaredNorm();
  // NaN or inf anywhere (or an overflowing square) makes the sum non-finite.
  if (!std::isfinite(mm + a + radius) || !(radius >= 0.0) || !(t_max >= 0.0)) {
    return no_contact(RaySphereStatus::Degenerate);
  }
  const double mmax = m.cwiseAbs().maxCoeff();
  const double tol = ray_sphere_tolerance_factor * std::numeric_limits<double>::epsilon() * mmax;
  const double outer = radius + tol;
  const double outer2 = outer * outer;
  if (mm <= outer2) {
    const double inner = radius - tol;
    if (inner > 0.0 && mm < inner * inner) return {RaySphereStatus::Overlapping, 0.0, Vec3::Zero()};
    // Within tol of the surface: touching at t = 0, whatever the direction.
    return {RaySphereStatus::Hit, 0.0, mm > 0.0 ? Vec3(m / std::sqrt(mm)) : Vec3::Zero()};
  }
  if (a < std::numeric_limits<double>::min()) return no_contact(RaySphereStatus::Degenerate);

  // From here on the outcome is Hit or Miss. Both candidate roots and the normal are
  // computed and the outcome is selected without branches: hits and misses are equally
  // likely in practice, and a mispredicted branch costs more than the work it skips.
  const double b = m.dot(direction);
  // a h^2 = |m x d|^2 (h: distance of the centre from the line), and the grazing-robust
  // discriminant D = a (R^2 - h^2): no b^2 - a k cancellation for grazing rays.
  const double c2 = m.cross(direction).squaredNorm();
  const double disc = a * (radius * radius) - c2;
  // Stable quadratic: for b < 0 the far root's q = -b + sqrt(D) has no cancellation, and
  // the near root is C / q with C = k = |m|^2 - R^2 > 0 (no cancellation when the origin
  // is near the surface). |D| keeps sqrt defined; a D <= 0 root is not selected.
  const double t_root = (mm - radius * radius) / (-b + std::sqrt(std::abs(disc)));
  // Grazing within tol (D <= 0 but h <= R + tol): contact at the closest approach -b/a.
  const double t_graze = -b * (1.0 / a);
  const double candidates[2] = {t_graze, t_root};
  const double t = candidates[disc > 0.0];
  // Hit: approaching (b < 0; outside with b >= 0 the distance only grows), the line within
  // tol of the sphere (h <= R + tol) and the root in range.
  const unsigned hit = static_cast<unsigned>(b < 0.0) & static_cast<unsigned>(c2 <= a * outer2) &
                       static_cast<unsigned>(t <= t_max);

  // Normal: the contact point relative to the centre, divided by R and renormalised by
  // one Newton step n *= (3 - |n|^2) / 2, which squares the length error d = |p|/R - 1.
  // |d| <= ~60 eps |m| / R (tol plus the radial part of the toi error), so for
  // R >= 1e-6 |m|_inf the step leaves |n| within a few eps of 1; smaller spheres (rare)
  // take the exact normalisation.
  // Selected by index rather than by a branch; a miss uses t = 0 so that p stays finite.
  const double t_normal[2] = {0.0, t};
  const Vec3 p = m + t_normal[hit] * direction;
  Vec3 n;
  if (radius >= 1e-6 * mmax) {
    n = p * (1.0 / radius);
    n *= 1.5 - 0.5 * n.squaredNorm();
  } else {
    const double pn = p.norm();
    n = pn > 0.0 ? Vec3(p / pn) : Vec3::Zero();
  }
  static constexpr RaySphereStatus outcome[2] = {RaySphereStatus::Miss, RaySphereStatus::Hit};
  static constexpr double miss_toi[2] = {kInf, 0.0};  // added to t: +inf on a miss
  static constexpr double keep[2] = {0.0, 1.0};
  return {outcome[hit], t + miss_toi[hit], keep[hit] * n};
}

}  // namespace ccd
