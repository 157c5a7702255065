// segment_polygon_closest: parallel, coplanar, through an edge or a vertex, crossing the
// face, beside it, far from the origin, a point segment (exact dyadic answers in comments);
// random segments against the certified GJK distance.
#include <catch2/catch.hpp>

#include <ccd/queries/convex_distance.hpp>
#include <ccd/queries/segment_polygon.hpp>
#include <tests/ccd/scene/scenery_support.hpp>

#include <random>

namespace ccd_queries_segment_polygon_test {

using namespace ccd;
using ccd::test::square_z;
using Status = SegmentPolygonResult::Status;

TEST_CASE("segment_polygon_closest: constructed cases", "[queries][scenery]") {
  const StaticPolygon sq = square_z(0, 0, 0, 1);  // [0,1]^2 at z = 0
  SECTION("parallel to the face at height 0.5: 0.25") {
    const auto r = segment_polygon_closest({-1, 0.5, 0.5}, {2, 0.5, 0.5}, sq);
    CHECK(r.distance_squared == 0.25);
  }
  SECTION("crossing the face: 0, at the crossing parameter 0.25") {
    const auto r = segment_polygon_closest({0.5, 0.5, 0.25}, {0.5, 0.5, -0.75}, sq);
    CHECK(r.status == Status::Crossing);
    CHECK(r.distance_squared == 0.0);
    CHECK(r.s == 0.25);
  }
  SECTION("through an edge (crossing the plane on x = 1): 0") {
    CHECK(segment_polygon_closest({1, 0.5, 1}, {1, 0.5, -1}, sq).distance_squared == 0.0);
  }
  SECTION("through a vertex: 0") {
    CHECK(segment_polygon_closest({0.5, 0.5, 1}, {1.5, 1.5, -1}, sq).distance_squared == 0.0);
  }
  SECTION("crossing the plane beside the polygon: the edge distance 0.5") {
    CHECK(segment_polygon_closest({1.5, 0.5, 1}, {1.5, 0.5, -1}, sq).distance_squared == 0.25);
  }
  SECTION("coplanar, across the polygon with both ends outside: 0") {
    CHECK(segment_polygon_closest({-1, 0.5, 0}, {2, 0.5, 0}, sq).distance_squared == 0.0);
  }
  SECTION("coplanar, outside: 0.25 from the edge y = 1") {
    CHECK(segment_polygon_closest({-1, 1.25, 0}, {2, 1.25, 0}, sq).distance_squared == 0.0625);
  }
  SECTION("an edge-parallel segment skew above the polygon's corner: 0.375^2 + 0.5^2") {
    // The line (1.375, 1.5, z) passes the vertex (1, 1, 0) at 0.625.
    CHECK(segment_polygon_closest({1.375, 1.5, 1}, {1.375, 1.5, -1}, sq).distance_squared == 0.390625);
  }
  SECTION("a point segment: the point's distance (0.75)") {
    CHECK(segment_polygon_closest({0.25, 0.5, 0.75}, {0.25, 0.5, 0.75}, sq).distance_squared == 0.5625);
  }
  SECTION("ending on the face: 0") {
    CHECK(segment_polygon_closest({0.5, 0.5, 1}, {0.5, 0.5, 0}, sq).distance_squared == 0.0);
  }
  SECTION("far from the origin (2^30): the same answers") {
    const double F = 1073741824.0;
    const StaticPolygon far = square_z(F, F, -F, 1);
    CHECK(segment_polygon_closest({F - 1, F + 0.5, -F + 0.5}, {F + 2, F + 0.5, -F + 0.5}, far).distance_squared == 0.25);
    CHECK(segment_polygon_closest({F + 1, F + 0.5, -F + 1}, {F + 1, F + 0.5, -F - 1}, far).distance_squared == 0.0);
    CHECK(segment_polygon_closest({F + 1.375, F + 1.5, -F + 1}, {F + 1.375, F + 1.5, -F - 1}, far).distance_squared ==
          0.390625);
  }
}

TEST_CASE("segment_polygon_closest: random segments against GJK", "[queries][scenery]") {
  std::mt19937_64 rng(1402);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int crossing = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 centre(u(rng), u(rng), u(rng));
    const StaticPolygon p = ccd::test::random_polygon(rng, centre, 1.0);
    const Vec3 a = centre + Vec3(u(rng), u(rng), u(rng));
    const Vec3 b = i % 4 == 0 ? a : centre + Vec3(u(rng), u(rng), u(rng));
    const auto r = segment_polygon_closest(a, b, p);
    crossing += r.status == Status::Crossing;
    const Vec3 seg[2] = {Vec3::Zero(), b - a};
    const ConvexDistance g = convex_distance(ConvexProxy{seg, 0.0}, ProxyPose{a, Eigen::Matrix3d::Identity()},
                                             ConvexProxy{p.vertices, 0.0}, ProxyPose{});
    const double d = std::sqrt(r.distance_squared);
    INFO("case " << i << " d " << d << " gjk [" << g.lower << ", " << g.upper << "]");
    CHECK(d >= std::max(0.0, g.lower) - 1e-12);
    CHECK(d <= std::max(0.0, g.upper) + 1e-12);
  }
  CHECK(crossing > 0);
}

}  // namespace ccd_queries_segment_polygon_test
