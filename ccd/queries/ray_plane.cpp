#include <ccd/queries/ray_plane.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <cmath>
#include <limits>

namespace ccd {

namespace {

static_assert(ray_plane_parallel_tolerance == 16.0 * kEps);

}  // namespace

RayPlaneResult ray_plane(const Vec3& origin, const Vec3& direction, const Vec3& normal, double offset,
                         double t_max) {
  const double nn = normal.squaredNorm();
  const double dd = direction.squaredNorm();
  const double scale = normal.cwiseProduct(origin).cwiseAbs().sum() + std::abs(offset);
  if (!std::isfinite(nn + dd + scale) || nn < std::numeric_limits<double>::min() || !(t_max >= 0.0)) {
    return {RayPlaneStatus::Degenerate, kInf};
  }
  const double residual = normal.dot(origin) - offset;  // signed distance times |n|
  const double denom = normal.dot(direction);
  constexpr double tau2 = ray_plane_parallel_tolerance * ray_plane_parallel_tolerance;
  const bool parallel = denom * denom <= tau2 * nn * dd;  // also true for a zero direction
  if (std::abs(residual) <= ray_plane_on_plane_factor * kEps * scale) {
    return {parallel ? RayPlaneStatus::InPlane : RayPlaneStatus::Hit, 0.0};
  }
  if (dd < std::numeric_limits<double>::min()) return {RayPlaneStatus::Degenerate, kInf};
  if (parallel) return {RayPlaneStatus::Parallel, kInf};
  const double t = -residual / denom;
  if (!(t >= 0.0 && t <= t_max)) return {RayPlaneStatus::Miss, kInf};
  return {RayPlaneStatus::Hit, t};
}

}  // namespace ccd
