#include "generator_test_support.hpp"

#include <catch2/catch.hpp>
#include <cmath>

namespace generators_lattice_test {

using ccdlab::testing::make;

TEST_CASE("lattice: neighbours touch exactly, nobody overlaps", "[generators]") {
  const double r = GENERATE(0.5, 0.25, 4.0);
  CAPTURE(r);
  // 64 = 4^3 bodies: a full cube of 3 * 4 * 4 * 3 = 144 touching neighbour pairs.
  const ccd::Scene s = make("lattice", {{"bodies", 64}, {"radius", r}});
  REQUIRE(s.bodies.size() == 64);
  CHECK(s.box->min == ccd::Vec3::Zero());
  CHECK(s.box->max == ccd::Vec3::Constant(10 * r));  // centres 2r .. 8r, one radius of clearance
  int touching = 0;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    CHECK(s.bodies[i].radius == r);
    CHECK(s.bodies[i].velocity == ccd::Vec3::Zero());
    for (int a = 0; a < 3; ++a) {
      // Equal coordinates: every coordinate is one of 2r, 4r, 6r, 8r, exactly.
      const double k = s.bodies[i].position[a] / (2 * r);
      CHECK(k == std::floor(k));
    }
    for (std::size_t j = i + 1; j < s.bodies.size(); ++j) {
      const double d = (s.bodies[j].position - s.bodies[i].position).norm();
      CHECK(d >= 2 * r);
      if (d == 2 * r) ++touching;
    }
  }
  CHECK(touching == 144);
  SECTION("velocities along one axis, of the given speed") {
    const ccd::Scene m = make("lattice", {{"bodies", 30}, {"radius", r}, {"speed", 0.125}});
    int axes[3] = {0, 0, 0};
    for (const ccd::Body& b : m.bodies) {
      int moving = 0;
      for (int a = 0; a < 3; ++a) {
        if (b.velocity[a] == 0.0) continue;
        ++moving;
        ++axes[a];
        CHECK(std::abs(b.velocity[a]) == 0.125);
      }
      CHECK(moving == 1);
    }
    for (int count : axes) CHECK(count > 0);
  }
}

TEST_CASE("lattice: the radius must be a power of two", "[generators]") {
  CHECK_THROWS_WITH(make("lattice", {{"radius", 0.3}}),
                    "parameter 'radius': must be a power of two, so that the lattice is exact (got 0.3)");
  CHECK_NOTHROW(make("lattice", {{"bodies", 9}, {"radius", 0.0625}}));
}

}  // namespace generators_lattice_test
