#pragma once
// Static polygons for the tests, built in C++: the plane (unit normal, offset) computed
// here from the vertices (Newell's area normal), random convex polygons.
#include <ccd/scene/scenery.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace ccd::test {

/// A polygon with `vertices` in order; normal = the normalised area normal (counter-clockwise
/// seen from it), offset = normal . v_0.
inline StaticPolygon make_polygon(std::vector<Vec3> vertices) {
  StaticPolygon p;
  p.vertices = std::move(vertices);
  Vec3 n = Vec3::Zero();
  const Vec3& v0 = p.vertices[0];
  for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i) n += (p.vertices[i] - v0).cross(p.vertices[i + 1] - v0);
  p.normal = n.normalized();
  p.offset = p.normal.dot(v0);
  return p;
}

/// The axis-aligned square [x0, x0 + s] x [y0, y0 + s] in the plane z = z0 (normal +z).
inline StaticPolygon square_z(double x0, double y0, double z0, double s) {
  return make_polygon({{x0, y0, z0}, {x0 + s, y0, z0}, {x0 + s, y0 + s, z0}, {x0, y0 + s, z0}});
}

/// A random convex polygon of m vertices (3..8 when m == 0) around `centre`, of size about
/// `size`, in a random plane: vertices on an ellipse at sorted random angles.
inline StaticPolygon random_polygon(std::mt19937_64& rng, const Vec3& centre, double size, int m = 0) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  if (m == 0) m = 3 + static_cast<int>(6 * u(rng)) % 6;
  Vec3 n;
  do { n = Vec3(g(rng), g(rng), g(rng)); } while (n.squaredNorm() < 1e-6);
  n.normalize();
  const Vec3 a = n.unitOrthogonal();
  const Vec3 b = n.cross(a);
  const double ra = size * (0.3 + u(rng)), rb = size * (0.3 + u(rng));
  std::vector<double> angles;
  for (int i = 0; i < m; ++i) angles.push_back(2.0 * M_PI * (i + 0.8 * u(rng)) / m);
  std::vector<Vec3> v;
  for (const double t : angles) v.push_back(centre + a * (ra * std::cos(t)) + b * (rb * std::sin(t)));
  return make_polygon(std::move(v));
}

}  // namespace ccd::test
