#include "generator_test_support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace generators_rain_test {

using ccdlab::testing::make;

TEST_CASE("rain: balls fall under gravity in a tall column", "[generators]") {
  const ccd::Scene s = make("rain", {{"bodies", 3000}, {"seed", 4}, {"aspect", 8.0}, {"speed_max", 0.5}});
  REQUIRE(s.bodies.size() == 3000);
  CHECK(s.gravity == ccd::Vec3(0.0, -9.81, 0.0));
  CHECK(s.motion_kind() == ccd::MotionKind::SharedAcceleration);
  const double width = s.box->max.x();
  CHECK(s.box->max.z() == width);
  CHECK(s.box->max.y() == 8.0 * width);
  // W^3 * aspect = N (4/3) pi E[r^3] / fraction, E[r^3] = (1 - 0.5^4) / (4 * 0.5) = 0.46875.
  CHECK(width * width * width * 8.0 ==
        Approx(3000 * (4.0 / 3.0) * std::numbers::pi * 0.46875 / 0.02).epsilon(16 * std::numeric_limits<double>::epsilon()));
  double mean_height = 0.0;
  for (const ccd::Body& b : s.bodies) {
    CHECK(b.velocity.y() == 0.0);
    CHECK(b.velocity.norm() <= 0.5);
    CHECK(b.radius >= 0.5);
    CHECK(b.radius <= 1.0);
    mean_height += b.position.y() / 3000;
  }
  // Heights uniform over the column: mean near half its height (std of the mean ~0.005 H).
  CHECK(mean_height == Approx(4.0 * width).epsilon(0.05));
  SECTION("no gravity makes it linear") {
    CHECK(make("rain", {{"bodies", 10}, {"gravity", 0.0}}).motion_kind() == ccd::MotionKind::Linear);
  }
}

}  // namespace generators_rain_test
