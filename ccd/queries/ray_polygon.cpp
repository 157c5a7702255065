#include <ccd/queries/ray_plane.hpp>
#include <ccd/geometry/numeric_limits.hpp>
#include <ccd/queries/ray_polygon.hpp>

#include <Eigen/Geometry>  // cross products

#include <cmath>
#include <limits>

namespace ccd {

namespace {

struct Point2 {
  double x;
  double y;
};

/// Ray frame: vertex v relative to the origin, projected along the ray onto the plane
/// that drops axis k. Computed per vertex only, so shared vertices project identically.
struct RayFrame {
  Vec3 origin;
  int i, j, k;
  double sx, sy;

  Point2 project(const Vec3& v) const {
    const double ri = v[i] - origin[i];
    const double rj = v[j] - origin[j];
    const double rk = v[k] - origin[k];
    return {ri - sx * rk, rj - sy * rk};
  }
};

/// Sign of the edge function of (a, b) at the ray point (0, 0), with ties broken by the
/// perturbation (d, d^2) of the point; 0 only for a zero-length projected edge.
int edge_sign(Point2 a, Point2 b) {
  const double e = a.x * b.y - a.y * b.x;
  if (e > 0.0) return 1;
  if (e < 0.0) return -1;
  const double ey = b.y - a.y;
  if (ey != 0.0) return ey > 0.0 ? -1 : 1;
  const double ex = b.x - a.x;
  return (ex > 0.0) - (ex < 0.0);
}

}  // namespace

RayPolygonResult ray_polygon(const Vec3& origin, const Vec3& direction, std::span<const Vec3> vertices,
                             double t_max) {
  const std::size_t n = vertices.size();
  if (n < 3) return {RayPolygonStatus::Degenerate, kInf};
  const Vec3& v0 = vertices[0];
  Vec3 normal = Vec3::Zero();
  for (std::size_t q = 1; q + 1 < n; ++q) normal += (vertices[q] - v0).cross(vertices[q + 1] - v0);

  const RayPlaneResult plane = ray_plane(origin - v0, direction, normal, 0.0, t_max);
  switch (plane.status) {
    case RayPlaneStatus::Degenerate:
      return {RayPolygonStatus::Degenerate, kInf};
    case RayPlaneStatus::Parallel:
      return {RayPolygonStatus::Parallel, kInf};
    case RayPlaneStatus::InPlane:
      return {RayPolygonStatus::Coplanar, 0.0};
    case RayPlaneStatus::Miss:
      return {RayPolygonStatus::Miss, kInf};
    case RayPlaneStatus::Hit:
      break;
  }

  RayFrame f{origin, 0, 1, 2, 0.0, 0.0};
  const Vec3 ad = direction.cwiseAbs();
  f.k = ad.x() >= ad.y() ? (ad.x() >= ad.z() ? 0 : 2) : (ad.y() >= ad.z() ? 1 : 2);
  f.i = (f.k + 1) % 3;
  f.j = (f.k + 2) % 3;
  f.sx = direction[f.i] / direction[f.k];
  f.sy = direction[f.j] / direction[f.k];

  int seen = 0;  // the common non-zero sign so far
  Point2 prev = f.project(vertices[n - 1]);
  for (std::size_t q = 0; q < n; ++q) {
    const Point2 cur = f.project(vertices[q]);
    const int s = edge_sign(prev, cur);
    if (s != 0) {
      if (seen != 0 && s != seen) return {RayPolygonStatus::Miss, kInf};
      seen = s;
    }
    prev = cur;
  }
  if (seen == 0) return {RayPolygonStatus::Miss, kInf};
  return {RayPolygonStatus::Hit, plane.toi};
}

}  // namespace ccd
