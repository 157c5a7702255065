#pragma once
// Static polygons for the tests, built in C++ (the plane derived by polygon_from_vertices):
// axis-aligned squares and random convex polygons.
#include <ccd/scene/scene.hpp>
#include <ccd/scene/scenery.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace ccd::test {

/// A polygon with `vertices` in order and its derived plane (polygon_from_vertices).
inline StaticPolygon make_polygon(std::vector<Vec3> vertices) { return polygon_from_vertices(std::move(vertices)); }

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

/// Balls falling fast (20-30 units/s down, gravity 8) through a stack of thin plates
/// (sixteen layers 1/4 apart of four 2 x 2 squares, dyadic) and 20 random tilted polygons, in
/// the box [0, 8] x [0, 8] x [-4, 12]: several plates per body and step of 1/16.
inline Scene plates_scene(std::uint64_t seed, int bodies) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.horizon = 1.0;
  s.gravity = Vec3(0, 0, -8);
  s.box = WallBox{Vec3(0, 0, -4), Vec3(8, 8, 12)};
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 4; ++j) s.scenery.push_back(square_z(2.0 * j, 2.0 * (k % 4), 0.25 * k - 1.0, 2.0));
  for (int k = 0; k < 20; ++k)
    s.scenery.push_back(random_polygon(rng, Vec3(8 * u(rng), 8 * u(rng), 4 * u(rng) - 1), 0.75));
  for (int i = 0; i < bodies; ++i) {
    Body b;
    b.radius = 0.0625 + 0.125 * u(rng);
    b.position = Vec3(0.5 + 7 * u(rng), 0.5 + 7 * u(rng), 6 + 4 * u(rng));
    b.velocity = Vec3(4 * u(rng) - 2, 4 * u(rng) - 2, -20 - 10 * u(rng));
    s.bodies.push_back(b);
  }
  return s;
}

}  // namespace ccd::test
