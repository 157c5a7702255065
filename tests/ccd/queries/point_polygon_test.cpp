// point_polygon_closest: constructed dyadic cases with the exact answer in a comment, and
// random points and polygons against the certified GJK distance (convex_distance).
#include <catch2/catch.hpp>

#include <ccd/queries/convex_distance.hpp>
#include <ccd/queries/point_polygon.hpp>
#include <tests/ccd/scene/scenery_support.hpp>

#include <random>

namespace ccd_queries_point_polygon_test {

using namespace ccd;
using ccd::test::make_polygon;
using ccd::test::square_z;

TEST_CASE("point_polygon_closest: constructed cases", "[queries][scenery]") {
  const StaticPolygon sq = square_z(0, 0, 0, 1);  // [0,1]^2 at z = 0
  SECTION("above the face: the height (0.75)") {
    const auto r = point_polygon_closest({0.25, 0.5, 0.75}, sq);
    CHECK(r.feature == PointPolygonResult::Feature::Face);
    CHECK(r.distance_squared == 0.5625);
    CHECK(r.closest == Vec3(0.25, 0.5, 0));
  }
  SECTION("below the face: two-sided (0.5)") {
    CHECK(point_polygon_closest({0.5, 0.5, -0.5}, sq).distance_squared == 0.25);
  }
  SECTION("in the plane, inside: 0") { CHECK(point_polygon_closest({0.5, 0.5, 0}, sq).distance_squared == 0.0); }
  SECTION("on an edge and on a vertex: 0") {
    CHECK(point_polygon_closest({1, 0.5, 0}, sq).distance_squared == 0.0);
    CHECK(point_polygon_closest({1, 1, 0}, sq).distance_squared == 0.0);
  }
  SECTION("beside an edge: 0.5^2 + 0.25^2") {
    const auto r = point_polygon_closest({1.5, 0.5, 0.25}, sq);
    CHECK(r.feature == PointPolygonResult::Feature::Edge);
    CHECK(r.distance_squared == 0.3125);
    CHECK(r.closest == Vec3(1, 0.5, 0));
  }
  SECTION("beyond a vertex: 0.375^2 + 0.5^2 = 0.625^2") {
    CHECK(point_polygon_closest({1.375, 1.5, 0}, sq).distance_squared == 0.390625);
  }
  SECTION("the other winding gives the same distances") {
    const StaticPolygon rev = make_polygon({{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}});
    CHECK(point_polygon_closest({0.25, 0.5, 0.75}, rev).distance_squared == 0.5625);
    CHECK(point_polygon_closest({1.5, 0.5, 0.25}, rev).distance_squared == 0.3125);
  }
  SECTION("far from the origin: the same answers at 2^30") {
    const double F = 1073741824.0;
    const StaticPolygon far = square_z(F, -F, F, 1);
    CHECK(point_polygon_closest({F + 0.25, -F + 0.5, F + 0.75}, far).distance_squared == 0.5625);
    CHECK(point_polygon_closest({F + 1.375, -F + 1.5, F}, far).distance_squared == 0.390625);
  }
  SECTION("a triangle in a tilted plane: the height above the face") {
    // Triangle in the plane x + y + z = 1 (normal (1,1,1)/sqrt 3); the point
    // (1,1,1)/3 + 0.5 n projects to its centroid: distance 0.5.
    const StaticPolygon tri = make_polygon({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    const Vec3 x = Vec3(1, 1, 1) / 3.0 + tri.normal * 0.5;
    CHECK(point_polygon_closest(x, tri).distance_squared == Approx(0.25).epsilon(1e-14));
  }
}

TEST_CASE("point_polygon_closest: random points against GJK", "[queries][scenery]") {
  std::mt19937_64 rng(1401);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 centre(u(rng), u(rng), u(rng));
    const StaticPolygon p = ccd::test::random_polygon(rng, centre, 1.0);
    const Vec3 x = centre + Vec3(u(rng), u(rng), u(rng)) * (i % 3 == 0 ? 0.1 : 1.0);
    const auto r = point_polygon_closest(x, p);
    const Vec3 origin = Vec3::Zero();
    const ConvexDistance g = convex_distance(ConvexProxy{{&origin, 1}, 0.0}, ProxyPose{x, Eigen::Matrix3d::Identity()},
                                             ConvexProxy{p.vertices, 0.0}, ProxyPose{});
    const double d = std::sqrt(r.distance_squared);
    INFO("case " << i << " d " << d << " gjk [" << g.lower << ", " << g.upper << "]");
    CHECK(d >= g.lower - 1e-12);
    CHECK(d <= g.upper + 1e-12);
    CHECK((x - r.closest).squaredNorm() == Approx(r.distance_squared).margin(1e-12));
  }
}

}  // namespace ccd_queries_point_polygon_test
