// The truth against an independent reference in IEEE quadruple precision (__float128,
// 113 bits): every body's position is recomputed from the scene's own numbers (initial
// state, acceleration and velocity changes; no walls, so that the reference needs no root solving),
// and the contact function is evaluated there. For every transversal event, the pair must
// be in contact at `enter` and not one double before, in contact at `exit` and not one
// double after (up to a tolerance far below what one ulp of time changes), and random
// instants outside every event must be out of contact.
#include <ccd/truth/ground_truth.hpp>

#include <tests/ccd/truth/reference_position.hpp>

#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace ccd_truth_quad_reference_test {

namespace {

using Q = __float128;

using QVec = std::array<Q, 3>;

Q f_q(const ccd::Scene& s, std::uint32_t i, std::uint32_t j, double t) {
  const QVec a = ccd::test::reference_position<Q>(s, s.bodies[i], t), b = ccd::test::reference_position<Q>(s, s.bodies[j], t);
  Q d2 = 0;
  for (int k = 0; k < 3; ++k) d2 += (b[k] - a[k]) * (b[k] - a[k]);
  const Q R = Q(s.bodies[i].radius) + Q(s.bodies[j].radius);
  return d2 - R * R;
}

// jumps: every third body also gets two velocity changes (drawn from their own generator,
// so the rest of the scene is the same).
ccd::Scene random_scene(std::uint64_t seed, double offset, bool jumps) {
  std::mt19937_64 rng(seed), jump_rng(seed + 1000);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ccd::Scene s;
  s.horizon = 2.0;
  s.gravity = ccd::Vec3(0, -9.81, 0);
  for (int i = 0; i < 300; ++i) {
    ccd::Body b;
    b.radius = 0.3 + 0.2 * u(rng);
    b.position = ccd::Vec3(offset + 6 * u(rng), offset + 6 * u(rng), offset + 6 * u(rng));
    b.velocity = ccd::Vec3(4 * u(rng), 4 * u(rng), 4 * u(rng));
    if (i % 3 != 0) b.acceleration = ccd::Vec3(3 * u(rng), 3 * u(rng), 3 * u(rng));  // quartic pairs
    if (i % 4 == 0) b.acceleration_changes.push_back({0.5 + 0.5 * (u(rng) + 1.0), ccd::Vec3(2 * u(rng), 0, 0)});
    if (jumps && i % 3 == 1) {
      const double t1 = 0.9 * (u(jump_rng) + 1.0) / 2.0 + 0.05;
      b.velocity_changes.push_back({t1, ccd::Vec3(4 * u(jump_rng), 4 * u(jump_rng), 4 * u(jump_rng))});
      b.velocity_changes.push_back({t1 + 0.75, ccd::Vec3(4 * u(jump_rng), 4 * u(jump_rng), 4 * u(jump_rng))});
    }
    if (jumps && i == 4) b.velocity_changes = {{b.acceleration_changes[0].t, ccd::Vec3(1, 2, 3)}};  // both at once
    s.bodies.push_back(b);
  }
  return s;
}

}  // namespace

TEST_CASE("the truth agrees with a quadruple-precision reference at every event end", "[truth][reference]") {
  const double offset = GENERATE(0.0, 1000.0, 100000.0);
  const bool jumps = GENERATE(false, true);  // velocity changes (docs/formats.md)
  CAPTURE(offset, jumps);
  const ccd::Scene s = random_scene(17 + static_cast<std::uint64_t>(offset), offset, jumps);
  const ccd::Trajectories traj(s);
  const auto events = ccd::compute_truth(traj);
  REQUIRE(events.size() > 50);
  // Far below the change of f over one ulp of time at a transversal crossing
  // (|f'| ulp(t) >= about 1e-17 here), far above quad and double-double rounding.
  const Q scale = Q(offset + 10) * Q(offset + 10);
  const Q tol = Q(1e-26) * scale;
  int checked = 0;
  for (const ccd::ContactEvent& e : events) {
    if (e.enter == e.exit) continue;  // tangencies: the time of a double root
    CAPTURE(e.a, e.b, e.enter, e.exit);
    if (e.enter > 0.0) {
      CHECK(f_q(s, e.a, e.b, e.enter) <= tol);
      CHECK(f_q(s, e.a, e.b, std::nextafter(e.enter, -1.0)) >= -tol);
    }
    if (e.exit < s.horizon) {
      CHECK(f_q(s, e.a, e.b, e.exit) <= tol);
      CHECK(f_q(s, e.a, e.b, std::nextafter(e.exit, 10.0)) >= -tol);
    }
    // The middle of the event is well inside.
    CHECK(f_q(s, e.a, e.b, 0.5 * (e.enter + e.exit)) <= tol);
    ++checked;
  }
  CHECK(checked > 50);
  // Random instants of random pairs that the truth says are apart are apart.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::uint32_t> body(0, static_cast<std::uint32_t>(s.bodies.size() - 1));
  std::uniform_real_distribution<double> when(0.0, s.horizon);
  int apart = 0;
  for (int k = 0; k < 20000; ++k) {
    std::uint32_t i = body(rng), j = body(rng);
    if (i == j) continue;
    if (i > j) std::swap(i, j);
    const double t = when(rng);
    bool inside = false;
    for (const ccd::ContactEvent& e : events) inside = inside || (e.a == i && e.b == j && e.enter <= t && t <= e.exit);
    if (!inside) {
      CHECK(f_q(s, i, j, t) >= -tol);
      ++apart;
    }
  }
  CHECK(apart > 10000);
}

}  // namespace ccd_truth_quad_reference_test
