// `floor_ramp`: the scenery it promises (docs/generators.md) and the contacts it makes (exact
// static truth, ccd/truth/static_truth.hpp).
#include "generator_test_support.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/truth/static_truth.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

namespace generators_floor_ramp_test {

using ccdlab::testing::make;
using nlohmann::json;

TEST_CASE("floor_ramp: balls slide down their ramps pressed into them, then bounce on the floor", "[generators][scenery]") {
  const ccd::Scene s = make("floor_ramp", {{"bodies", 24}, {"ramps", 3}, {"horizon", 2.0}, {"seed", 4}});
  REQUIRE(s.scenery.size() == 4);  // the floor, then one polygon per ramp
  CHECK(s.scenery[0].normal.cwiseAbs() == ccd::Vec3(0, 1, 0));
  CHECK(s.gravity == ccd::Vec3(0, -9.81, 0));
  const ccd::Trajectories t(s);
  const auto ev = ccd::compute_static_truth(t, s.scenery, 1);
  for (std::uint32_t i = 0; i < s.bodies.size(); ++i) {
    CAPTURE(i);
    // In contact with its own ramp (polygon 1 + i % 3) from t = 0 until about when the
    // acceleration change lets it fall.
    REQUIRE(s.bodies[i].acceleration_changes.size() == 1);
    const double t_end = s.bodies[i].acceleration_changes[0].t;
    const auto ramp = std::find_if(ev.begin(), ev.end(), [&](const ccd::StaticEvent& e) {
      return e.body == i && e.polygon == 1 + i % 3 && e.enter == 0.0;
    });
    REQUIRE(ramp != ev.end());
    CHECK(ramp->exit >= t_end * (1 - 1e-9));
    CHECK(ramp->exit < t_end + 0.5);
    // Then at least one real (not tangent) contact with the floor.
    CHECK(std::any_of(ev.begin(), ev.end(), [&](const ccd::StaticEvent& e) {
      return e.body == i && e.polygon == 0 && e.enter > t_end && e.exit > e.enter;
    }));
  }
}

}  // namespace generators_floor_ramp_test
