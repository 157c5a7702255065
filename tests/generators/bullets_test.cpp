#include "generator_test_support.hpp"

#include <catch2/catch.hpp>
#include <limits>

namespace generators_bullets_test {

using ccdlab::testing::make;

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}

TEST_CASE("bullets: small fast spheres aimed at field bodies", "[generators]") {
  const ccd::Scene s = make("bullets", {{"bodies", 300}, {"bullets", 25}, {"seed", 8}});
  REQUIRE(s.bodies.size() == 300);
  const std::size_t field = 275;
  for (std::size_t i = 0; i < field; ++i) {
    CHECK(s.bodies[i].radius >= 0.5);
    CHECK(s.bodies[i].velocity.norm() <= 1.0 * (1 + 4 * eps));
  }
  for (std::size_t i = field; i < s.bodies.size(); ++i) {
    const ccd::Body& b = s.bodies[i];
    CHECK(b.radius == 0.05);
    // 200 * (d / |d|): a few roundings of at most eps/2 each.
    CHECK(b.velocity.norm() == Approx(200.0).epsilon(4 * eps));
    // The line of flight passes through some field body's centre at t = 0: the distance
    // of that centre from the line, relative to the box size, is a few eps.
    const ccd::Vec3 dir = b.velocity.normalized();
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < field; ++j) {
      const ccd::Vec3 d = s.bodies[j].position - b.position;
      if (d.dot(dir) > 0) nearest = std::min(nearest, (d - d.dot(dir) * dir).norm());
    }
    CHECK(nearest <= 16 * eps * s.box->max.x());
  }
  SECTION("more bullets than bodies: all are bullets") {
    const ccd::Scene all = make("bullets", {{"bodies", 5}, {"bullets", 10}});
    for (const ccd::Body& b : all.bodies) CHECK(b.radius == 0.05);
  }
  SECTION("no bullets: only the field") {
    const ccd::Scene none = make("bullets", {{"bodies", 5}, {"bullets", 0}});
    for (const ccd::Body& b : none.bodies) CHECK(b.radius >= 0.5);
  }
}

}  // namespace generators_bullets_test
