#include <ccd/queries/ray_sphere.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

RaySphereResult no_contact(RaySphereStatus status) { return {status, inf, Vec3::Zero()}; }

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
  const double tol = ray_sphere_tolerance_factor * std::numeric_limits<double>::epsilon() * m.cwiseAbs().maxCoeff();
  const double outer = radius + tol;
  const double outer2 = outer * outer;
  if (mm <= outer2) {
    const double inner = radius - tol;
    if (inner > 0.0 && mm < inner * inner) return {RaySphereStatus::Overlapping, 0.0, Vec3::Zero()};
    // Within tol of the surface: touching at t = 0, whatever the direction.
    return {RaySphereStatus::Hit, 0.0, mm > 0.0 ? Vec3(m / std::sqrt(mm)) : Vec3::Zero()};
  }
  if (a < std::numeric_limits<double>::min()) return no_contact(RaySphereStatus::Degenerate);
  const double b = m.dot(direction);
  if (b >= 0.0) return no_contact(RaySphereStatus::Miss);  // outside and not approaching
  // Squared distance of the centre from the line (grazing-robust discriminant D = a w2).
  const Vec3 e = m - (b / a) * direction;
  const double h2 = e.squaredNorm();
  if (h2 > outer2) return no_contact(RaySphereStatus::Miss);
  const double w2 = radius * radius - h2;  // squared half chord
  double t = 0.0;
  if (w2 <= 0.0) {
    t = -b / a;  // grazing within tol: contact at the closest approach
  } else {
    // Stable quadratic: the far root (-b + sqrt D)/a has no cancellation for b < 0; the
    // near root is C/q with C = k = |m|^2 - R^2 > 0.
    const double q = -b + std::sqrt(a * w2);
    t = (mm - radius * radius) / q;
  }
  if (!(t <= t_max)) return no_contact(RaySphereStatus::Miss);
  const Vec3 p = m + t * direction;
  const double pn = p.norm();
  return {RaySphereStatus::Hit, t, pn > 0.0 ? Vec3(p / pn) : Vec3::Zero()};
}

}  // namespace ccd
