#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

// Rounds a computed radius up: sqrt and the sums before it are each within an ulp or two
// of exact, so 8 ulps above the computed value is above the exact one.
double round_up(double r) { return r * (1.0 + 8.0 * std::numeric_limits<double>::epsilon()); }

}  // namespace

void Shape::build_points() {
  switch (kind) {
    case ShapeKind::Sphere: points = {Vec3::Zero()}; break;
    case ShapeKind::Capsule: points = {Vec3(-half_length, 0, 0), Vec3(half_length, 0, 0)}; break;
    case ShapeKind::Box: {
      points.clear();
      for (int i = 0; i < 8; ++i)
        points.emplace_back((i & 1) ? half_extents.x() : -half_extents.x(),
                            (i & 2) ? half_extents.y() : -half_extents.y(),
                            (i & 4) ? half_extents.z() : -half_extents.z());
      break;
    }
    case ShapeKind::Hull: break;
  }
}

double Shape::enclosing_radius() const {
  switch (kind) {
    case ShapeKind::Sphere: return radius;
    case ShapeKind::Capsule: return round_up(half_length + radius);
    case ShapeKind::Box: return round_up(half_extents.norm());
    case ShapeKind::Hull: {
      double m = 0.0;
      for (const Vec3& p : points) m = std::max(m, p.norm());
      return round_up(m);
    }
  }
  return radius;
}

Shape make_sphere_shape(double radius, std::string name) {
  Shape s;
  s.name = std::move(name);
  s.kind = ShapeKind::Sphere;
  s.radius = radius;
  s.build_points();
  return s;
}

Shape make_capsule_shape(double half_length, double radius, std::string name) {
  Shape s;
  s.name = std::move(name);
  s.kind = ShapeKind::Capsule;
  s.half_length = half_length;
  s.radius = radius;
  s.build_points();
  return s;
}

Shape make_box_shape(const Vec3& half_extents, std::string name) {
  Shape s;
  s.name = std::move(name);
  s.kind = ShapeKind::Box;
  s.half_extents = half_extents;
  s.build_points();
  return s;
}

Shape make_hull_shape(std::vector<Vec3> points, std::string name) {
  Shape s;
  s.name = std::move(name);
  s.kind = ShapeKind::Hull;
  s.points = std::move(points);
  return s;
}

std::string hull_degeneracy(const std::vector<Vec3>& pts) {
  if (pts.size() < 4) return "a hull needs at least 4 points (it has " + std::to_string(pts.size()) + ")";
  double scale = 0.0;
  for (const Vec3& p : pts) scale = std::max(scale, p.norm());
  const double tol = 1e-9 * scale;
  // The two points furthest apart along the farthest from pts[0]; then the point furthest
  // from their line; then the point furthest from the plane of the three.
  auto farthest = [&](auto dist) {
    std::size_t best = 0;
    double bd = -1.0;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (const double d = dist(pts[i]); d > bd) bd = d, best = i;
    return std::pair{best, bd};
  };
  const Vec3 p0 = pts[0];
  const auto [i1, d1] = farthest([&](const Vec3& p) { return (p - p0).norm(); });
  if (!(d1 > tol)) return "all points coincide (the hull has no volume)";
  const Vec3 p1 = pts[i1];
  const Vec3 u = (p1 - p0) / d1;
  const auto [i2, d2] = farthest([&](const Vec3& p) { return (p - p0 - u * u.dot(p - p0)).norm(); });
  if (!(d2 > tol)) return "all points lie on one line (the hull has no volume)";
  const Vec3 n = u.cross(pts[i2] - p0).normalized();
  const auto [i3, d3] = farthest([&](const Vec3& p) { return std::fabs(n.dot(p - p0)); });
  (void)i3;
  if (!(d3 > tol)) return "all points are coplanar (the hull has no volume)";
  return {};
}

}  // namespace ccd
