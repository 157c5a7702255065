#include <ccd/truth/pair_contact.hpp>

#include <tests/ccd/scene/body_builder.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_truth_pair_contact_test {

using ccd::Body;
using ccd::ContactInterval;
using ccd::Scene;
using ccd::Trajectories;
using ccd::Vec3;
using ccd::test::body;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<ContactInterval> intervals(const Trajectories& t, double u0, double u1) {
  std::vector<ContactInterval> out;
  ccd::pair_contact_intervals(t, 0, 1, u0, u1, out);
  return out;
}

// Times in these scenes are small binary fractions; allow a few ulps of the horizon.
double time_tol(double horizon) { return 16 * kEps * horizon; }

}  // namespace

TEST_CASE("pair contact intervals across trajectory pieces", "[truth][pair]") {
  Scene s;
  s.horizon = 10.0;
  SECTION("head-on, the whole horizon: [4, 6]") {
    s.bodies = {body(1, {0, 0, 0}, {1, 0, 0}), body(1, {10, 0, 0}, {-1, 0, 0})};
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 10);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == Approx(4.0).margin(time_tol(10)));
    CHECK(iv[0].exit == Approx(6.0).margin(time_tol(10)));
    const auto first = ccd::pair_first_contact(t, 0, 1, 0, 10);
    REQUIRE(first);
    CHECK(*first == iv[0].enter);
  }
  SECTION("contact running past the horizon ends there; windows clip") {
    s.horizon = 5.0;
    s.bodies = {body(1, {0, 0, 0}, {1, 0, 0}), body(1, {10, 0, 0}, {-1, 0, 0})};
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 5);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].exit == 5.0);
    const auto w = intervals(t, 4.5, 4.75);  // a window inside the contact
    REQUIRE(w.size() == 1);
    CHECK((w[0].enter == 4.5 && w[0].exit == 4.75));
    CHECK(*ccd::pair_first_contact(t, 0, 1, 4.5, 4.75) == 4.5);
    CHECK(!ccd::pair_first_contact(t, 0, 1, 0.0, 3.5));
    CHECK(intervals(t, 0.0, 3.5).empty());
  }
  SECTION("contact started before 0 starts at 0") {
    s.bodies = {body(1, {0, 0, 0}, {1, 0, 0}), body(1, {1, 0, 0}, {-1, 0, 0})};
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 10);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == 0.0);
    CHECK(iv[0].exit == Approx(1.5).margin(time_tol(10)));  // separation 1 - 2t reaches -2
  }
  SECTION("wall bounce: contact after a reflection, merged across a second reflection") {
    // Box [0,10]^3. Body 0 (r 1) at x = 5 moving +2 reflects at x = 9 (t = 2) and at x = 1
    // (t = 6). Body 1 (r 1) rests at x = 2. Contact while |x0 - 2| <= 2, i.e. x0 <= 4:
    // from t = 4.5 (x0 = 4 going down) through the reflection at t = 6 to t = 7.5.
    s.box = ccd::WallBox{{0, 0, 0}, {10, 10, 10}};
    s.bodies = {body(1, {5, 5, 5}, {2, 0, 0}), body(1, {2, 5, 5})};
    const Trajectories t(s);
    REQUIRE(t.pieces(0).size() >= 3);
    const auto iv = intervals(t, 0, 10);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == Approx(4.5).margin(time_tol(10)));
    CHECK(iv[0].exit == Approx(7.5).margin(time_tol(10)));
    CHECK(*ccd::pair_first_contact(t, 0, 1, 0, 10) == iv[0].enter);
    CHECK(*ccd::pair_first_contact(t, 0, 1, 6, 10) == 6.0);
  }
  SECTION("wall bounce while touching at the reflection: a tangent point at the break") {
    // Body 0 reaches the wall x = 9 at t = 2 where body 1 (r 1, at x = 9, y = 7) touches it
    // from the side: distance exactly 2 at t = 2, and again at t = 10 (after the reflection
    // at x = 1, t = 6, it is back at x = 9): two touching points.
    s.box = ccd::WallBox{{0, 0, 0}, {10, 10, 10}};
    s.bodies = {body(1, {5, 5, 5}, {2, 0, 0}), body(1, {9, 7, 5})};
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 10);
    REQUIRE(iv.size() == 2);
    CHECK(iv[0].enter == iv[0].exit);
    CHECK(iv[0].enter == Approx(2.0).margin(time_tol(10)));
    CHECK((iv[1].enter == 10.0 && iv[1].exit == 10.0));
    CHECK(intervals(t, 0, 9.5).size() == 1);
  }
  SECTION("gravity with a floor: shared acceleration, contact after a bounce") {
    // Both fall under gravity; body 0 is lower and bounces off the floor, meeting body 1
    // on the way up. Reference by dense sampling below.
    s.gravity = {0, -9.81, 0};
    s.box = ccd::WallBox{{0, 0, 0}, {10, 100, 10}};
    s.bodies = {body(0.5, {5, 3, 5}), body(0.5, {5, 8, 5})};
    s.horizon = 2.0;
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 2);
    REQUIRE(!iv.empty());
    for (int k = 0; k <= 20000; ++k) {
      const double tt = 2.0 * k / 20000.0;
      const double d = (t.position(1, tt) - t.position(0, tt)).norm();
      bool inside = false;
      for (const auto& x : iv) inside = inside || (x.enter <= tt && tt <= x.exit);
      if (d < 1.0 - 1e-9) REQUIRE(inside);
      if (d > 1.0 + 1e-9) REQUIRE(!inside);
    }
  }
  SECTION("acceleration change: body 0 accelerates to speed 2, then coasts: [4.5, 6.5]") {
    // x0 = t^2 on [0,1], then 1 + 2 (t-1). Body 1 at x = 10, R = 2: x0 in [8, 12].
    Body b0 = body(1, {0, 0, 0}, {0, 0, 0}, {2, 0, 0});
    b0.acceleration_changes = {{1.0, Vec3::Zero()}};
    s.bodies = {b0, body(1, {10, 0, 0})};
    const Trajectories t(s);
    REQUIRE(t.pieces(0).size() == 2);
    const auto iv = intervals(t, 0, 10);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == Approx(4.5).margin(time_tol(10)));
    CHECK(iv[0].exit == Approx(6.5).margin(time_tol(10)));
  }
  SECTION("acceleration change during contact: one merged interval") {
    // Body 0 overlaps body 1 from t = 0 and stays so across its acceleration change at 1.
    Body b0 = body(1, {0, 0, 0}, {0, 0, 0}, {0.5, 0, 0});
    b0.acceleration_changes = {{1.0, Vec3(-0.5, 0, 0)}};
    s.bodies = {b0, body(1, {1, 0, 0})};
    s.horizon = 2.0;
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 2);
    REQUIRE(iv.size() == 1);
    CHECK((iv[0].enter == 0.0 && iv[0].exit == 2.0));
  }
  SECTION("different accelerations: quartic with two intervals") {
    // Relative x(t) = (t-1)(t-3), R = 0.5 (see the sphere test).
    s.bodies = {body(0.25, {0, 0, 0}), body(0.25, {3, 0, 0}, {-4, 0, 0}, {2, 0, 0})};
    s.horizon = 5.0;
    const Trajectories t(s);
    const auto iv = intervals(t, 0, 5);
    REQUIRE(iv.size() == 2);
    const double tol = 1e-12;  // well-conditioned simple roots, checked to eps in the query tests
    CHECK(iv[0].enter == Approx(2 - std::sqrt(1.5)).margin(tol));
    CHECK(iv[1].exit == Approx(2 + std::sqrt(1.5)).margin(tol));
  }
}

TEST_CASE("pair_first_contact equals the first interval on random windows", "[truth][pair]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.horizon = 3.0;
  s.gravity = {0, -9.81, 0};
  s.box = ccd::WallBox{{0, 0, 0}, {4, 4, 4}};
  for (int i = 0; i < 12; ++i) {
    Body b = body(0.3 + 0.3 * u(rng), {1.2 + 1.6 * u(rng), 1.2 + 1.6 * u(rng), 1.2 + 1.6 * u(rng)},
                  {8 * u(rng) - 4, 8 * u(rng) - 4, 8 * u(rng) - 4}, {2 * u(rng) - 1, 0, 2 * u(rng) - 1});
    if (i % 3 == 0) b.acceleration_changes = {{1.5, Vec3(0, 3, 0)}};
    s.bodies.push_back(b);
  }
  const Trajectories t(s);
  int compared = 0;
  for (std::uint32_t a = 0; a < 12; ++a) {
    for (std::uint32_t b = a + 1; b < 12; ++b) {
      for (int w = 0; w < 20; ++w) {
        double u0 = 3 * u(rng), u1 = 3 * u(rng);
        if (u0 > u1) std::swap(u0, u1);
        std::vector<ContactInterval> iv;
        ccd::pair_contact_intervals(t, a, b, u0, u1, iv);
        const auto first = ccd::pair_first_contact(t, a, b, u0, u1);
        REQUIRE(first.has_value() == !iv.empty());
        if (first) {
          REQUIRE(*first == iv.front().enter);
          ++compared;
        }
        for (const auto& x : iv) REQUIRE((u0 <= x.enter && x.enter <= x.exit && x.exit <= u1));
      }
    }
  }
  CHECK(compared > 20);
}

}  // namespace ccd_truth_pair_contact_test
