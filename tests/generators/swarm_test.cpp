#include "generator_test_support.hpp"

#include <catch2/catch.hpp>

namespace generators_swarm_test {

using ccdlab::testing::make;

TEST_CASE("swarm: accelerations bounded by max_acceleration, changing at known times", "[generators]") {
  const ccd::Scene s = make("swarm", {{"bodies", 2000}, {"seed", 6}, {"max_acceleration", 7.5},
                                      {"changes", 6}, {"horizon", 2.0}});
  REQUIRE(s.bodies.size() == 2000);
  CHECK(s.motion_kind() == ccd::MotionKind::PiecewiseQuadratic);
  CHECK(s.max_acceleration() <= 7.5);
  double largest = 0.0;
  for (const ccd::Body& b : s.bodies) {
    CHECK(b.acceleration.norm() <= 7.5);  // exact bound: draws are retried until it holds
    REQUIRE(b.acceleration_changes.size() == 6);
    double prev = 0.0;
    for (const ccd::AccelerationChange& c : b.acceleration_changes) {
      CHECK(c.acceleration.norm() <= 7.5);
      CHECK(c.t > prev);
      CHECK(c.t < 2.0);
      prev = c.t;
      largest = std::max(largest, c.acceleration.norm());
    }
  }
  // Uniform in the ball: 12000 draws come close to the bound.
  CHECK(largest > 0.99 * 7.5);
  SECTION("regular times are horizon k / (changes + 1) for every body") {
    const ccd::Scene r = make("swarm", {{"bodies", 20}, {"changes", 3}, {"regular", 1}, {"horizon", 2.0}});
    for (const ccd::Body& b : r.bodies) {
      REQUIRE(b.acceleration_changes.size() == 3);
      CHECK(b.acceleration_changes[0].t == 0.5);
      CHECK(b.acceleration_changes[1].t == 1.0);
      CHECK(b.acceleration_changes[2].t == 1.5);
    }
  }
  SECTION("no changes: constant accelerations that differ") {
    CHECK(make("swarm", {{"bodies", 20}, {"changes", 0}}).motion_kind() == ccd::MotionKind::Quadratic);
  }
  SECTION("zero bound: no acceleration at all") {
    const ccd::Scene z = make("swarm", {{"bodies", 20}, {"max_acceleration", 0.0}});
    CHECK(z.max_acceleration() == 0.0);
  }
}

}  // namespace generators_swarm_test
