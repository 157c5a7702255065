#include <generators/sampling.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace generators_sampling_test {

using ccd::Vec3;

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}

TEST_CASE("uniform draws are the engine's top 53 bits", "[generators]") {
  ccdlab::Random r(42);
  std::mt19937_64 engine(42);
  for (int i = 0; i < 1000; ++i) {
    const double u = r.uniform();
    CHECK(u == static_cast<double>(engine() >> 11) / 9007199254740992.0);
    CHECK(u >= 0.0);
    CHECK(u < 1.0);
  }
}

TEST_CASE("directions are unit vectors with no preferred side", "[generators]") {
  ccdlab::Random r(5);
  Vec3 sum = Vec3::Zero();
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = r.direction();
    // x / sqrt(|x|^2): a few roundings, each at most eps/2 relative.
    CHECK(std::abs(d.norm() - 1.0) <= 4 * eps);
    sum += d;
  }
  // Mean of n uniform unit vectors: each component has standard deviation 1/sqrt(3n)
  // (0.004 here); 0.03 is more than 7 of them.
  CHECK(sum.norm() / n < 0.03);
}

TEST_CASE("ball and disc draws never exceed their radius in floating point", "[generators]") {
  ccdlab::Random r(9);
  for (int i = 0; i < 20000; ++i) {
    const double radius = 20.0 + i * 1e-3;
    CHECK(r.in_ball(radius).norm() <= radius);
    const Vec3 d = r.in_horizontal_disc(radius);
    CHECK(d.norm() <= radius);
    CHECK(d.y() == 0.0);
  }
  SECTION("zero radius gives zero") { CHECK(r.in_ball(0.0) == Vec3::Zero()); }
}

TEST_CASE("coordinates keep the sphere inside the walls as validate_scene tests it", "[generators]") {
  ccdlab::Random r(3);
  SECTION("ordinary") {
    for (int i = 0; i < 20000; ++i) {
      const double p = r.coordinate(0.0, 40.0, 1.5);
      CHECK(!(p - 1.5 < 0.0));
      CHECK(!(p + 1.5 > 40.0));
    }
  }
  SECTION("tightest allowed walls, 4 radii apart, far from the origin") {
    for (int i = 0; i < 20000; ++i) {
      const double p = r.coordinate(1e6, 1e6 + 4.0 * 0.1, 0.1);
      CHECK(!(p - 0.1 < 1e6));
      CHECK(!(p + 0.1 > 1e6 + 0.4));
    }
  }
  SECTION("walls too close") { CHECK_THROWS_AS(r.coordinate(0.0, 1.0, 0.3), std::logic_error); }
}

TEST_CASE("index draws stay below n", "[generators]") {
  ccdlab::Random r(1);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 30000; ++i) ++counts[r.index(3)];
  // Each count is binomial(30000, 1/3): mean 10000, standard deviation 82.
  for (int c : counts) CHECK(std::abs(c - 10000) < 600);
}

TEST_CASE("box side from the volume fraction", "[generators]") {
  // U[0.5, 1.5]: E[r^3] = (1.5^4 - 0.5^4) / 4 = 1.25.
  CHECK(ccdlab::mean_cube_uniform(0.5, 1.5) == 1.25);
  CHECK(ccdlab::mean_cube_uniform(2.0, 2.0) == 8.0);
  // log-uniform on [1, e]: (e^3 - 1) / 3.
  CHECK(ccdlab::mean_cube_log_uniform(1.0, std::numbers::e) ==
        Approx((std::exp(3.0) - 1.0) / 3.0).epsilon(8 * eps));
  const double side = ccdlab::cube_side(2000, 1.25, 0.02, 1.5);
  CHECK(2000 * 4.0 / 3.0 * std::numbers::pi * 1.25 / (side * side * side) == Approx(0.02).epsilon(8 * eps));
  SECTION("never smaller than 4 r_max") {
    CHECK(ccdlab::cube_side(0, 1.25, 0.02, 1.5) == 6.0);
    CHECK(ccdlab::cube_side(1, 1.25, 0.49, 1.5) == 6.0);
  }
}

}  // namespace generators_sampling_test
