// `pinball`: the scenery it promises (docs/generators.md) and the contacts it makes (exact
// static truth, ccd/truth/static_truth.hpp).
#include "generator_test_support.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/truth/static_truth.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

namespace generators_pinball_test {

using ccdlab::testing::make;
using nlohmann::json;

TEST_CASE("pinball: thin obstacles, fast balls that cross them", "[generators][scenery]") {
  const ccd::Scene s = make("pinball", {{"bodies", 40}, {"obstacles", 60}, {"seed", 9}});
  REQUIRE(s.scenery.size() == 60);
  for (const ccd::StaticPolygon& p : s.scenery) {
    CHECK(p.normal.y() == 0.0);  // upright
    CHECK((p.vertices[1] - p.vertices[0]).norm() == Approx(0.5));
  }
  const auto ev = ccd::compute_static_truth(ccd::Trajectories(s), s.scenery, 1);
  // 40 balls at 20 m/s for 1 s among 60 obstacles in 10 m x 10 m: many crossings, and a
  // step of 1/60 s moves a ball 0.33 m, over three times the largest diameter.
  CHECK(ev.size() >= 40);
}

}  // namespace generators_pinball_test
