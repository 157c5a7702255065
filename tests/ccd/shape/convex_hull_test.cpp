// The convex hull's surface (ccd/shape/convex_hull.hpp): closed, outward, every point on or
// behind every face; many coplanar points; thousands of points on a sphere.
#include <ccd/shape/convex_hull.hpp>
#include <ccd/shape/mass_properties.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>
#include <vector>

namespace ccd_shape_convex_hull_test {

using ccd::Vec3;

namespace {

// Every edge of the surface is used once in each direction (closed), and no point lies in
// front of a face by more than the tolerance (outward and convex).
void check_surface(const std::vector<Vec3>& points, const std::vector<std::array<Vec3, 3>>& faces) {
  REQUIRE_FALSE(faces.empty());
  auto key = [](const Vec3& a, const Vec3& b) { return std::tuple(a.x(), a.y(), a.z(), b.x(), b.y(), b.z()); };
  std::map<std::tuple<double, double, double, double, double, double>, int> edges;
  double scale = 0.0;
  for (const Vec3& p : points) scale = std::max(scale, p.norm());
  double worst = 0.0;
  for (const auto& f : faces) {
    for (int e = 0; e < 3; ++e) ++edges[key(f[e], f[(e + 1) % 3])];
    const Vec3 n = (f[1] - f[0]).cross(f[2] - f[0]).normalized();
    for (const Vec3& p : points) worst = std::max(worst, n.dot(p - f[0]));
  }
  CHECK(worst <= 1e-8 * scale);
  int open = 0;
  for (const auto& [e, count] : edges) {
    const auto [ax, ay, az, bx, by, bz] = e;
    const auto twin = edges.find(std::tuple(bx, by, bz, ax, ay, az));
    open += count != 1 || twin == edges.end() || twin->second != 1;
  }
  CHECK(open == 0);
}

}  // namespace

TEST_CASE("the convex hull of a cube's surface grid: closed, and the cube's mass properties", "[shape][hull]") {
  // 11 x 11 points on each face (many coplanar and collinear), and points inside.
  std::vector<Vec3> pts;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0}) {
          Vec3 p;
          p[axis] = side;
          p[(axis + 1) % 3] = -1.0 + 0.2 * i;
          p[(axis + 2) % 3] = -1.0 + 0.2 * j;
          pts.push_back(p);
        }
  pts.push_back(Vec3(0.1, -0.2, 0.3));
  check_surface(pts, ccd::convex_hull_triangles(pts));
  const ccd::MassProperties cube = ccd::mass_properties(ccd::make_box_shape(Vec3(1, 1, 1)), 1.0);
  const ccd::MassProperties hull = ccd::mass_properties(ccd::make_hull_shape(pts), 1.0);
  CHECK(hull.volume == Approx(8.0).epsilon(1e-12));
  CHECK(hull.centre.norm() <= 1e-12);
  CHECK((hull.inertia - cube.inertia).norm() <= 1e-12 * cube.inertia.norm());
}

TEST_CASE("the convex hull of 3,000 points on a sphere and 1,000 inside", "[shape][hull]") {
  std::vector<Vec3> pts;
  const int n = 3000;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z), a = 2.399963229728653 * i;
    pts.emplace_back(r * std::cos(a), r * std::sin(a), z);
    if (i % 3 == 0) pts.push_back(0.9 * pts.back());  // inside
  }
  const auto faces = ccd::convex_hull_triangles(pts);
  check_surface(pts, faces);
  CHECK(faces.size() == 2 * n - 4);  // every sphere point a vertex (Euler: F = 2 V - 4)
  const double volume = ccd::mass_properties(ccd::make_hull_shape(pts), 1.0).volume;
  CHECK(volume < 4.0 / 3.0 * std::numbers::pi);
  CHECK(volume > 0.995 * 4.0 / 3.0 * std::numbers::pi);
}

TEST_CASE("degenerate point sets have no hull faces", "[shape][hull]") {
  CHECK(ccd::convex_hull_triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).empty());
  CHECK(ccd::convex_hull_triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}}).empty());
  CHECK(ccd::convex_hull_triangles({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).empty());
}

}  // namespace ccd_shape_convex_hull_test
