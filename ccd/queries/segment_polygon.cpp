#include <ccd/queries/point_polygon.hpp>
#include <ccd/queries/segment_polygon.hpp>
#include <ccd/queries/segment_segment.hpp>

#include <algorithm>
#include <cstdint>

namespace ccd {

SegmentPolygonResult segment_polygon_closest(const Vec3& p0, const Vec3& p1, const StaticPolygon& polygon) {
  SegmentPolygonResult out;
  const auto& v = polygon.vertices;
  const std::size_t m = v.size();
  const Vec3& n = polygon.normal;
  const double h0 = (p0 - v[0]).dot(n);
  const double h1 = (p1 - v[0]).dot(n);
  // Crossing or touching the plane strictly between or at the ends with opposite signs.
  if ((h0 <= 0.0 && h1 >= 0.0) || (h0 >= 0.0 && h1 <= 0.0)) {
    if (h0 != h1) {
      const double s = h0 / (h0 - h1);
      const Vec3 x = p0 + (p1 - p0) * s;
      if (projects_inside(x, polygon)) {
        out.status = SegmentPolygonResult::Status::Crossing;
        out.s = s;
        out.distance_squared = 0.0;
        return out;
      }
    }
  }
  const PointPolygonResult e0 = point_polygon_closest(p0, polygon);
  const PointPolygonResult e1 = point_polygon_closest(p1, polygon);
  out.status = SegmentPolygonResult::Status::Endpoint;
  out.s = e1.distance_squared < e0.distance_squared ? 1.0 : 0.0;
  out.distance_squared = std::min(e0.distance_squared, e1.distance_squared);
  if ((p1 - p0).squaredNorm() == 0.0) return out;
  const Vec3 r0 = p0 - v[0], r1 = p1 - v[0];
  for (std::size_t i = 0; i < m; ++i) {
    const SegmentSegmentResult c = segment_segment_closest(r0, r1, v[i] - v[0], v[(i + 1) % m] - v[0]);
    if (c.distance_squared < out.distance_squared) {
      out.distance_squared = c.distance_squared;
      out.s = c.s;
      out.edge = static_cast<std::uint32_t>(i);
      out.status = SegmentPolygonResult::Status::Edge;
    }
  }
  return out;
}

}  // namespace ccd
