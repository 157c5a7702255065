#include "generator_test_support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace generators_gas_test {

using ccdlab::testing::make;
using nlohmann::json;

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}

TEST_CASE("gas: radii, speeds and box follow the parameters", "[generators]") {
  const json p = {{"bodies", 4000}, {"seed", 2}, {"r_min", 0.25}, {"r_max", 0.75}, {"speed_max", 3.0},
                  {"fraction", 0.05}};
  const ccd::Scene s = make("gas", p);
  REQUIRE(s.bodies.size() == 4000);
  CHECK(s.motion_kind() == ccd::MotionKind::Linear);
  CHECK(s.gravity == ccd::Vec3::Zero());
  // L = cbrt(N (4/3) pi E[r^3] / fraction), E[r^3] = (0.75^4 - 0.25^4) / (4 * 0.5) = 0.15625.
  const double side = std::cbrt(4000 * (4.0 / 3.0) * std::numbers::pi * 0.15625 / 0.05);
  CHECK(s.box->min == ccd::Vec3::Zero());
  CHECK(s.box->max.x() == Approx(side).epsilon(8 * eps));
  CHECK(s.box->max.y() == s.box->max.x());
  CHECK(s.box->max.z() == s.box->max.x());
  double volume = 0.0;
  double mean_speed = 0.0;
  ccd::Vec3 mean_position = ccd::Vec3::Zero();
  for (const ccd::Body& b : s.bodies) {
    CHECK(b.radius >= 0.25);
    CHECK(b.radius <= 0.75);
    // speed * unit direction: the direction's norm is 1 within a few eps.
    CHECK(b.velocity.norm() <= 3.0 * (1 + 4 * eps));
    CHECK(b.acceleration == ccd::Vec3::Zero());
    volume += 4.0 / 3.0 * std::numbers::pi * b.radius * b.radius * b.radius;
    mean_speed += b.velocity.norm() / 4000;
    mean_position += b.position / 4000;
  }
  // Sample statistics of 4000 draws (fixed seed); each bound is several standard deviations.
  CHECK(volume / (side * side * side) == Approx(0.05).epsilon(0.05));  // fraction of the box filled
  CHECK(mean_speed == Approx(1.5).epsilon(0.05));                      // U[0, 3] has mean 1.5
  CHECK((mean_position - ccd::Vec3::Constant(side / 2)).norm() < 0.05 * side);
  SECTION("equal radii") {
    const ccd::Scene e = make("gas", {{"bodies", 50}, {"r_min", 1.0}, {"r_max", 1.0}});
    for (const ccd::Body& b : e.bodies) CHECK(b.radius == 1.0);
  }
  SECTION("zero speed: everything at rest") {
    const ccd::Scene z = make("gas", {{"bodies", 50}, {"speed_max", 0.0}});
    for (const ccd::Body& b : z.bodies) CHECK(b.velocity.isZero(0.0));
  }
}

}  // namespace generators_gas_test
