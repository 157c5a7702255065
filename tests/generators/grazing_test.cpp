#include "generator_test_support.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/truth/ground_truth.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>

namespace generators_grazing_test {

using ccdlab::testing::make;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("grazing: pairs pass at exactly the intended distance and time", "[generators]") {
  const double r = GENERATE(0.5, 0.125, 2.0);
  const double speed = 8.0, tick = 1.0 / 64;
  CAPTURE(r);
  // 40 bodies = 20 pairs: kinds q mod 4 (tangent, one ulp beyond, shallow, near miss),
  // closest approach on the tick grid when (q / 4) is even.
  const ccd::Scene s = make("grazing", {{"bodies", 40}, {"radius", r}, {"seed", 3}});
  REQUIRE(s.bodies.size() == 40);
  const double R = 2 * r;
  for (std::size_t q = 0; q < 20; ++q) {
    CAPTURE(q);
    const ccd::Body& rest = s.bodies[2 * q];
    const ccd::Body& pass = s.bodies[2 * q + 1];
    CHECK(rest.radius == r);
    CHECK(pass.radius == r);
    CHECK(rest.velocity == ccd::Vec3::Zero());
    CHECK(pass.velocity == ccd::Vec3(speed, 0, 0));
    CHECK(pass.position.z() == rest.position.z());
    const double h = pass.position.y() - rest.position.y();  // exact (Sterbenz)
    const double t_close = (rest.position.x() - pass.position.x()) / speed;
    CHECK(t_close > 0.0);
    CHECK(t_close < s.horizon);
    // On-grid times are whole ticks; off-grid ones lie a quarter tick or more from any.
    const double ticks = t_close / tick;
    if ((q / 4) % 2 == 0) {
      CHECK(ticks == std::floor(ticks));
    } else {
      CHECK(std::abs(ticks - std::round(ticks)) >= 0.25 - 1e-12);
    }
    switch (q % 4) {
      case 0: CHECK(h == R); break;
      case 1:
        CHECK(h > R);
        CHECK(h == std::nextafter(rest.position.y() + R, kInf) - rest.position.y());
        break;
      case 2: CHECK(h == Approx(R * (1 - 1e-6)).epsilon(1e-12)); break;
      case 3: CHECK(h == Approx(R * (1 + 1e-6)).epsilon(1e-12)); break;
    }
  }
}

TEST_CASE("grazing: the truth has a tangent event per tangent pair, an interval per crossing", "[generators]") {
  // 33 bodies: 16 pairs and one lone resting body (odd count).
  const ccd::Scene s = make("grazing", {{"bodies", 33}, {"seed", 9}});
  const ccd::Trajectories traj(s);
  const std::vector<ccd::ContactEvent> events = ccd::compute_truth(traj);
  std::map<std::size_t, int> events_of_pair;
  for (const ccd::ContactEvent& e : events) {
    // Only the two bodies of one pair ever meet.
    REQUIRE(e.a % 2 == 0);
    REQUIRE(e.b == e.a + 1);
    const std::size_t q = e.a / 2;
    ++events_of_pair[q];
    const double t_close = (s.bodies[e.a].position.x() - s.bodies[e.b].position.x()) / 8.0;
    CAPTURE(q, e.enter, e.exit, t_close);
    if (q % 4 == 2) {
      CHECK(e.enter < t_close);  // a shallow crossing: a short interval around t_close
      CHECK(e.exit > t_close);
    } else {
      REQUIRE(q % 4 == 0);  // one ulp beyond and near misses are separations
      CHECK(e.enter == e.exit);  // tangent: a point
      CHECK(e.enter == Approx(t_close).margin(1e-9));
    }
  }
  for (std::size_t q = 0; q < 16; ++q) {
    CAPTURE(q);
    CHECK(events_of_pair[q] == (q % 4 == 0 || q % 4 == 2 ? 1 : 0));  // near misses have no event
  }
}

TEST_CASE("grazing: radius, speed and tick must be powers of two, tick <= horizon / 2", "[generators]") {
  CHECK_THROWS_WITH(make("grazing", {{"radius", 0.3}}),
                    "parameter 'radius': must be a power of two, so that tangent contacts are exact (got 0.3)");
  CHECK_THROWS_WITH(make("grazing", {{"speed", 10}}), Catch::Matchers::StartsWith("parameter 'speed': must be"));
  CHECK_THROWS_WITH(make("grazing", {{"tick", 0.01}}), Catch::Matchers::StartsWith("parameter 'tick': must be"));
  CHECK_THROWS_WITH(make("grazing", {{"tick", 1}}), "tick (1) must be <= horizon / 2 (0.5)");
  CHECK_NOTHROW(make("grazing", {{"tick", 0.5}, {"bodies", 8}}));
}

}  // namespace generators_grazing_test
