#include "generator_test_support.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

namespace generators_mixed_test {

using ccdlab::testing::make;

TEST_CASE("mixed: radii span three orders of magnitude, log-uniformly", "[generators]") {
  SECTION("100 bodies reach both ends") {
    const ccd::Scene s = make("mixed", {{"bodies", 100}, {"seed", 9}});
    const auto [lo, hi] = std::minmax_element(s.bodies.begin(), s.bodies.end(),
                                              [](const ccd::Body& a, const ccd::Body& b) { return a.radius < b.radius; });
    CHECK(lo->radius == 0.01);
    CHECK(hi->radius == 10.0);
    CHECK(hi->radius / lo->radius >= 1000.0);
  }
  SECTION("each decade holds about a third") {
    const ccd::Scene s = make("mixed", {{"bodies", 3000}, {"seed", 9}});
    int decade[3] = {0, 0, 0};
    for (const ccd::Body& b : s.bodies) {
      REQUIRE(b.radius >= 0.01);
      REQUIRE(b.radius <= 10.0);
      ++decade[std::min(2, static_cast<int>(std::floor(std::log10(b.radius / 0.01))))];
    }
    // Binomial(3000, 1/3): standard deviation 26; 200 is more than 7 of them.
    for (int count : decade) CHECK(std::abs(count - 1000) < 200);
  }
}

}  // namespace generators_mixed_test
