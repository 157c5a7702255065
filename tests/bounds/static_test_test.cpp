// Bound::test_static of every bound in the registry: zero false negatives. If the sphere
// (its true path in the step) touches a polygon at time tc, the test must say Possible with
// earliest <= tc. Constructed dyadic cases with a known contact time (tangent to a face,
// moving parallel to a face at distance exactly r, grazing an edge and a vertex, contact
// at t0 and at t1, after a wall reflection, after an acceleration change, far from the
// origin, at rest), and random steps whose contacts are certified at sample times by the
// GJK distance (convex_distance's upper bound <= r: the sphere truly touches).
#include <catch2/catch.hpp>

#include <bounds/registry.hpp>
#include <ccd/broad_phase/static_index.hpp>
#include <ccd/queries/convex_distance.hpp>
#include <tests/bounds/bound_test_support.hpp>
#include <tests/ccd/scene/body_builder.hpp>
#include <tests/ccd/scene/scenery_support.hpp>

#include <random>
#include <string>

namespace bounds_static_test_test {

using namespace ccd;
using ccd::test::make_polygon;
using ccd::test::square_z;

namespace {

struct StaticCase {
  std::string name;
  Scene scene;            // one body
  StaticPolygon polygon;
  double t0 = 0.0, t1 = 1.0;
  double tc = 0.0;        // a time of contact in [t0, t1]
};

std::vector<StaticCase> constructed_cases() {
  std::vector<StaticCase> cs;
  const StaticPolygon sq = square_z(0, 0, 0, 1);  // [0,1]^2 at z = 0
  auto add = [&](std::string name, Body b, StaticPolygon p, double t0, double t1, double tc,
                 std::optional<WallBox> box = std::nullopt) {
    StaticCase c;
    c.name = std::move(name);
    c.scene.horizon = 2.0;
    c.scene.box = box;
    c.scene.bodies.push_back(std::move(b));
    c.polygon = std::move(p);
    c.t0 = t0;
    c.t1 = t1;
    c.tc = tc;
    cs.push_back(std::move(c));
  };
  // Falls onto the face, tangent exactly at t1 = 1 (z = r = 0.25 at t = 1).
  add("tangent to the face at t1", ccd::test::body(0.25, {0.5, 0.5, 2.25}, {0, 0, -2}), sq, 0.0, 1.0, 1.0);
  // Starts touching at t0 and leaves.
  add("touching at t0, leaving", ccd::test::body(0.25, {0.5, 0.5, 0.25}, {0, 0, 3}), sq, 0.0, 1.0, 0.0);
  // Slides parallel to the face at height exactly r, entering over the edge x = 0 at t = 0.5.
  add("parallel to the face at distance r", ccd::test::body(0.25, {-1, 0.5, 0.25}, {2, 0, 0}), sq, 0.0, 1.0, 0.5);
  // In the polygon's plane, passing the edge x = 1 at distance r (closest at every t).
  add("grazing an edge", ccd::test::body(0.5, {1.5, -2, 0}, {0, 4, 0}), sq, 0.0, 1.0, 0.5);
  // Down the line (1.375, 1.5, z): passes the vertex (1, 1, 0) at 0.625 = r at t = 0.5.
  add("grazing a vertex", ccd::test::body(0.625, {1.375, 1.5, 1}, {0, 0, -2}), sq, 0.0, 1.0, 0.5);
  // At rest at distance exactly r below the face.
  add("at rest, touching", ccd::test::body(0.5, {0.5, 0.75, -0.5}, Vec3::Zero()), sq, 0.0, 1.0, 0.0);
  // A fast ball through a thin polygon: crosses the plane at t = 0.5.
  add("tunnelling through", ccd::test::body(0.125, {0.5, 0.5, 50}, {0, 0, -100}), sq, 0.0, 1.0, 0.5);
  {
    // Acceleration change: falls with a = -4 until t = 0.25 (z = 0.875, v = -1), then glides
    // at constant velocity: z = 0.25 at t = 0.875.
    Body b = ccd::test::body(0.25, {0.5, 0.5, 1}, Vec3::Zero(), {0, 0, -4});
    b.acceleration_changes.push_back({0.25, Vec3::Zero()});
    add("after an acceleration change", b, sq, 0.0, 1.0, 0.875);
  }
  {
    // Wall reflection: box [0, 8]^3; from (1, 2, 2) at (-4, 8, 0) the ball (r = 0.25) reflects
    // off x = 0 at t = 0.1875 (x = 0.25, y = 3.5) and then reaches the polygon in the plane
    // x = 1.5 (y in [5, 7], z in [1, 3]) at t = 0.4375 (x = 1.25, y = 5.5); the unreflected
    // path never does.
    const StaticPolygon wallside = make_polygon({{1.5, 5, 1}, {1.5, 7, 1}, {1.5, 7, 3}, {1.5, 5, 3}});
    add("after a wall reflection", ccd::test::body(0.25, {1, 2, 2}, {-4, 8, 0}), wallside, 0.0, 0.5, 0.4375,
        WallBox{Vec3::Zero(), Vec3::Constant(8)});
    // Contact exactly at the reflection: the polygon y = 3.75 (x in [0, 1]) is touched when
    // the ball reflects (y = 3.5 = 3.75 - r) at t = 0.1875.
    const StaticPolygon at_wall = make_polygon({{0, 3.75, 1}, {0, 3.75, 3}, {1, 3.75, 3}, {1, 3.75, 1}});
    add("contact at the wall reflection", ccd::test::body(0.25, {1, 2, 2}, {-4, 8, 0}), at_wall, 0.0, 0.5, 0.1875,
        WallBox{Vec3::Zero(), Vec3::Constant(8)});
  }
  {
    // Far from the origin: the tangent-at-t1 case moved by (2^30, -2^30, 2^29).
    const Vec3 F(1073741824.0, -1073741824.0, 536870912.0);
    add("far from the origin, tangent at t1", ccd::test::body(0.25, Vec3(0.5, 0.5, 2.25) + F, {0, 0, -2}),
        square_z(F.x(), F.y(), F.z(), 1), 0.0, 1.0, 1.0);
  }
  // A later step window [0.5, 1]: contact at its start.
  add("contact at a later step's start", ccd::test::body(0.25, {0.5, 0.5, 1.25}, {0, 0, -2}), sq, 0.5, 1.0, 0.5);
  return cs;
}

// The bound's answer for body 0 (of `step`) against `polygon` over its step.
PairTest static_answer(const BoundInfo& info, const test::Step& step, const StaticPolygon& polygon,
                       std::uint32_t body = 0) {
  auto bound = info.make();
  std::vector<Aabb> boxes;
  bound->prepare(step.context(info.knowledge), boxes);
  return bound->test_static(body, boxes[body], polygon, polygon_box(polygon));
}

}  // namespace

TEST_CASE("Bound::test_static: constructed contacts, every bound", "[bounds][scenery]") {
  for (const StaticCase& c : constructed_cases()) {
    test::Step step;
    step.scene = c.scene;
    step.finish(c.t0, c.t1);
    for (const BoundInfo& info : bound_registry()) {
      // An instant bound sees the sample time t0 only: it owes an answer when tc == t0.
      if (info.knowledge == Knowledge::Instant && c.tc != c.t0) continue;
      INFO(c.name << " / " << info.name);
      const PairTest t = static_answer(info, step, c.polygon);
      REQUIRE(t.possible());
      CHECK(t.earliest <= c.tc);
      CHECK(t.earliest >= c.t0);
    }
  }
}

TEST_CASE("Bound::test_static: far polygons are disjoint for the tight bounds", "[bounds][scenery]") {
  // The ball (r = 0.25) falls from z = 2.25 to 0.25 over [0, 1] above (0.5, 0.5); the polygon
  // is the square [0,1]^2 lifted to x in [3, 4]: 2.25 away in x. Every bound but the
  // loosest may say Possible; the exact-motion and instant ones must not.
  test::Step step;
  step.scene.horizon = 1.0;
  step.scene.bodies.push_back(ccd::test::body(0.25, {0.5, 0.5, 2.25}, {0, 0, -2}));
  step.finish(0.0, 1.0);
  const StaticPolygon far = square_z(3, 0, 0, 1);
  for (const char* name : {"sphere", "aabb", "swept_aabb", "capsule", "horn", "enclosing_sphere"}) {
    INFO(name);
    CHECK_FALSE(static_answer(*parse_bound(name).info, step, far).possible());
  }
  // A polygon touching the capsule's box (x = 0.75) but apart from the capsule: the box
  // default would say Possible, the capsule's segment distance does not. The tilted
  // triangle x + z = 3.25 passes 0.5 / sqrt 2 ~ 0.354 > r = 0.25 from the path's top.
  const StaticPolygon diag = make_polygon({{0.75, -1, 2.5}, {0.75, 2, 2.5}, {1.75, 0.5, 1.5}});
  CHECK(static_answer(*parse_bound("capsule").info, step, diag).possible() == false);
}

TEST_CASE("Bound::test_static: random steps, contacts certified at sample times", "[bounds][scenery]") {
#ifdef CCDLAB_SANITIZED
  const int rounds = 4;
#else
  const int rounds = 12;
#endif
  std::mt19937_64 rng(1405);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int contacts = 0;
  for (int round = 0; round < rounds; ++round) {
    const bool walls = round % 2 == 0;
    test::Step step = test::random_gas(rng, 12, 0.0, 0.25, 8.0, walls, round % 3 == 0, 2);
    // Polygons placed at sampled positions of the bodies (some touched, some nearly).
    std::vector<StaticPolygon> polygons;
    for (std::size_t b = 0; b < step.scene.bodies.size(); ++b) {
      const double ts = step.t0 + (step.t1 - step.t0) * u(rng);
      const Vec3 x = step.traj.position(b, ts);
      polygons.push_back(test::random_polygon(rng, x + test::random_vec(rng, 2.0 * step.traj.radius(b)), 0.5));
    }
    // Certified contacts at 65 sample times: GJK upper bound on the centre's distance <= r.
    for (const BoundInfo& info : bound_registry()) {
      auto bound = info.make();
      std::vector<Aabb> boxes;
      bound->prepare(step.context(info.knowledge), boxes);
      const int samples = info.knowledge == Knowledge::Instant ? 1 : 65;
      for (std::uint32_t b = 0; b < step.scene.bodies.size(); ++b) {
        for (std::uint32_t p = 0; p < polygons.size(); ++p) {
          double first = std::numeric_limits<double>::infinity();
          for (int k = 0; k < samples; ++k) {
            const double t = step.t0 + (step.t1 - step.t0) * k / 64.0;
            const Vec3 x = step.traj.position(b, t);
            const Vec3 origin = Vec3::Zero();
            const ConvexDistance g = convex_distance(ConvexProxy{{&origin, 1}, 0.0},
                                                     ProxyPose{x, Eigen::Matrix3d::Identity()},
                                                     ConvexProxy{polygons[p].vertices, 0.0}, ProxyPose{});
            if (g.upper <= step.traj.radius(b)) {
              first = t;
              break;
            }
          }
          if (!(first < std::numeric_limits<double>::infinity())) continue;
          ++contacts;
          const PairTest t = bound->test_static(b, boxes[b], polygons[p], polygon_box(polygons[p]));
          INFO(info.name << " round " << round << " body " << b << " polygon " << p << " first " << first);
          REQUIRE(t.possible());
          CHECK(t.earliest <= first);
        }
      }
    }
  }
  CHECK(contacts > 20);
}

}  // namespace bounds_static_test_test
