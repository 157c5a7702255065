#include <ccd/queries/point_polygon.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace ccd {

bool projects_inside(const Vec3& x, const StaticPolygon& polygon) {
  const auto& v = polygon.vertices;
  const std::size_t m = v.size();
  if (m < 3) return false;
  const Vec3 rx = x - v[0];
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 a = v[i] - v[0];
    const Vec3 b = v[(i + 1) % m] - v[0];
    if ((b - a).cross(rx - a).dot(polygon.normal) < 0.0) return false;
  }
  return polygon.normal.squaredNorm() > 0.0;
}

PointPolygonResult point_polygon_closest(const Vec3& x, const StaticPolygon& polygon) {
  PointPolygonResult out;
  const auto& v = polygon.vertices;
  const std::size_t m = v.size();
  if (m == 0) {
    out.distance_squared = std::numeric_limits<double>::infinity();
    return out;
  }
  const Vec3 rx = x - v[0];
  if (projects_inside(x, polygon)) {
    const double h = rx.dot(polygon.normal);  // signed height above the plane through v_0
    out.feature = PointPolygonResult::Feature::Face;
    out.closest = x - polygon.normal * h;
    out.distance_squared = h * h;
    return out;
  }
  out.feature = PointPolygonResult::Feature::Edge;
  out.distance_squared = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 a = v[i] - v[0];
    const Vec3 d = v[(i + 1) % m] - v[i];
    const double dd = d.squaredNorm();
    const double u = dd > 0.0 ? std::clamp((rx - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    const Vec3 c = a + d * u;
    const double q = (rx - c).squaredNorm();
    if (q < out.distance_squared) {
      out.distance_squared = q;
      out.edge = static_cast<std::uint32_t>(i);
      out.closest = v[0] + c;
    }
  }
  return out;
}

}  // namespace ccd
