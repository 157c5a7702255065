#include <ccd/scene/scenery.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

namespace ccd {
namespace {

Vec3 area_normal(const std::vector<Vec3>& v) {
  Vec3 n = Vec3::Zero();
  for (std::size_t i = 1; i + 1 < v.size(); ++i) n += (v[i] - v[0]).cross(v[i + 1] - v[0]);
  return n;
}

std::string number(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}

}  // namespace

StaticPolygon polygon_from_vertices(std::vector<Vec3> vertices) {
  StaticPolygon p;
  const Vec3 n = area_normal(vertices);
  const double len = n.norm();
  if (len > 0.0 && std::isfinite(len)) {
    p.normal = n / len;
    p.offset = p.normal.dot(vertices[0]);
  }
  p.vertices = std::move(vertices);
  return p;
}

std::optional<PolygonDefect> polygon_defect(const std::vector<Vec3>& v) {
  const std::size_t n = v.size();
  if (n < 3) return PolygonDefect{-1, "needs at least 3 vertices, has " + std::to_string(n)};
  for (std::size_t i = 0; i < n; ++i)
    if (!v[i].allFinite()) return PolygonDefect{static_cast<std::ptrdiff_t>(i), "must be finite"};
  double size = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) size = std::max(size, (v[i] - v[j]).norm());
  const double tol = kPolygonTolerance * size;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if ((v[i] - v[j]).norm() <= tol)
        return PolygonDefect{static_cast<std::ptrdiff_t>(j), "repeats vertex " + std::to_string(i)};
  // Collinear: vertex i within tol of the line through its neighbours.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = v[(i + n - 1) % n];
    const Vec3& b = v[(i + 1) % n];
    const Vec3 d = b - a;
    const double dist = d.cross(v[i] - a).norm() / d.norm();
    if (dist <= tol)
      return PolygonDefect{static_cast<std::ptrdiff_t>(i),
                           "is collinear with its neighbours (vertices " + std::to_string((i + n - 1) % n) + " and " +
                               std::to_string((i + 1) % n) + ")"};
  }
  const Vec3 an = area_normal(v);
  if (!(an.norm() > 0.0)) return PolygonDefect{-1, "has zero area"};
  const Vec3 normal = an.normalized();
  // Planar: distances from the plane through the centroid along the area normal; the
  // worst vertex is named.
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& x : v) centroid += (x - v[0]) / static_cast<double>(n);
  centroid += v[0];
  std::size_t worst = 0;
  double worst_h = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double h = std::fabs(normal.dot(v[i] - centroid));
    if (h > worst_h) {
      worst_h = h;
      worst = i;
    }
  }
  if (worst_h > tol)
    return PolygonDefect{static_cast<std::ptrdiff_t>(worst),
                         "is " + number(worst_h) + " from the polygon's plane: not planar (tolerance " +
                             number(kPolygonTolerance) + " x size " + number(size) + ")"};
  // Convex and winding once: every vertex on the inner side of every edge's line.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = v[i];
    const Vec3 e = v[(i + 1) % n] - a;
    const Vec3 m = normal.cross(e).normalized();  // inward for counter-clockwise about normal
    for (std::size_t k = 0; k < n; ++k) {
      if (k == i || k == (i + 1) % n) continue;
      if (m.dot(v[k] - a) <= tol)
        return PolygonDefect{static_cast<std::ptrdiff_t>(k),
                             "lies outside the edge from vertex " + std::to_string(i) + " to " +
                                 std::to_string((i + 1) % n) + ": not convex"};
    }
  }
  return std::nullopt;
}

}  // namespace ccd
