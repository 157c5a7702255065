#include <ccd/shape/shape.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace ccd_shape_shape_test {

using ccd::Vec3;

TEST_CASE("shape kinds round-trip through their names", "[shape]") {
  for (std::size_t k = 0; k < ccd::kShapeKinds; ++k) {
    const auto kind = static_cast<ccd::ShapeKind>(k);
    REQUIRE(ccd::shape_kind_from_string(ccd::to_string(kind)) == kind);
  }
  CHECK_FALSE(ccd::shape_kind_from_string("cylinder"));
  CHECK_FALSE(ccd::shape_kind_from_string(""));
}

TEST_CASE("proxies: sphere one point, capsule two, box eight corners", "[shape]") {
  const ccd::Shape s = ccd::make_sphere_shape(0.5);
  REQUIRE(s.points.size() == 1);
  CHECK(s.proxy().radius == 0.5);
  const ccd::Shape c = ccd::make_capsule_shape(1.0, 0.125);
  REQUIRE(c.points.size() == 2);
  CHECK(c.points[0] == Vec3(-1, 0, 0));
  CHECK(c.points[1] == Vec3(1, 0, 0));
  CHECK(c.proxy().radius == 0.125);
  const ccd::Shape b = ccd::make_box_shape(Vec3(0.5, 0.25, 0.125));
  REQUIRE(b.points.size() == 8);
  CHECK(b.proxy().radius == 0.0);
  // The support along (1, 1, 1) is the corner (+, +, +), along (-1, 1, -1) the corner (-, +, -).
  CHECK(b.points[b.proxy().support_index(Vec3(1, 1, 1))] == Vec3(0.5, 0.25, 0.125));
  CHECK(b.points[b.proxy().support_index(Vec3(-1, 1, -1))] == Vec3(-0.5, 0.25, -0.125));
}

TEST_CASE("the enclosing radius is never below the exact one and at most a few ulps above", "[shape]") {
  const double u = std::numeric_limits<double>::epsilon();
  SECTION("sphere: the radius itself") { CHECK(ccd::make_sphere_shape(0.3).enclosing_radius() == 0.3); }
  SECTION("capsule: half_length + radius (1.25 exactly, rounded up by at most 8 ulps)") {
    const double r = ccd::make_capsule_shape(1.0, 0.25).enclosing_radius();
    CHECK(r >= 1.25);
    CHECK(r <= 1.25 * (1 + 9 * u));
  }
  SECTION("box 3-4-12 half extents: |h| = 13 exactly") {
    const double r = ccd::make_box_shape(Vec3(3, 4, 12)).enclosing_radius();
    CHECK(r >= 13.0);
    CHECK(r <= 13.0 * (1 + 9 * u));
  }
  SECTION("box 0.1-0.2-0.3 (not dyadic): above sqrt(0.14) computed in long double") {
    const double r = ccd::make_box_shape(Vec3(0.1, 0.2, 0.3)).enclosing_radius();
    const long double exact = std::sqrt(0.1L * 0.1L + 0.2L * 0.2L + 0.3L * 0.3L);
    CHECK(static_cast<long double>(r) >= exact);
  }
  SECTION("hull: the furthest point") {
    const ccd::Shape h = ccd::make_hull_shape({{0.3, 0, 0}, {0, 0.4, 0}, {0, 0, 0.2}, {-0.2, -0.1, -0.1}});
    CHECK(h.enclosing_radius() >= 0.4);
    CHECK(h.enclosing_radius() <= 0.4 * (1 + 9 * u));
  }
}

TEST_CASE("hull degeneracy: too few, coincident, collinear and coplanar points", "[shape]") {
  // A tetrahedron spans a volume.
  CHECK(ccd::hull_degeneracy({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}).empty());
  SECTION("three points") { CHECK(ccd::hull_degeneracy({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).find("at least 4") != std::string::npos); }
  SECTION("four equal points") {
    CHECK(ccd::hull_degeneracy({{2, 2, 2}, {2, 2, 2}, {2, 2, 2}, {2, 2, 2}}).find("coincide") != std::string::npos);
  }
  SECTION("collinear, far from the origin") {
    CHECK(ccd::hull_degeneracy({{1e6, 0, 0}, {1e6 + 1, 0, 0}, {1e6 + 2, 0, 0}, {1e6 + 0.5, 0, 0}}).find("one line") !=
          std::string::npos);
  }
  SECTION("coplanar: a square and its centre") {
    CHECK(ccd::hull_degeneracy({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}}).find("coplanar") !=
          std::string::npos);
  }
  SECTION("a flat tetrahedron 1e-12 thick on a unit scale is coplanar; 1e-6 thick is not") {
    CHECK_FALSE(ccd::hull_degeneracy({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1e-12}}).empty());
    CHECK(ccd::hull_degeneracy({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1e-6}}).empty());
  }
}

}  // namespace ccd_shape_shape_test
