#include <ccd/queries/aabb_sweep.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <limits>
#include <random>

namespace ccd_queries_aabb_sweep_test {

using ccd::Aabb;
using ccd::AabbSweepStatus;
using ccd::Vec3;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

const Aabb unit{Vec3(0, 0, 0), Vec3(1, 1, 1)};

}  // namespace

TEST_CASE("aabb_sweep hand-worked intervals", "[queries][aabb_sweep]") {
  const Vec3 still = Vec3::Zero();
  SECTION("approach along x: b at x in [3,4] moving at -4 touches at 0.5, last at 1") {
    // first = (a.hi - b.lo) / v = (1 - 3) / -4, last = (a.lo - b.hi) / v = (0 - 4) / -4.
    const Aabb b{Vec3(3, 0, 0), Vec3(4, 1, 1)};
    const auto r = ccd::aabb_sweep(unit, still, b, Vec3(-4, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 0.5);
    CHECK(r.t_last == 1.0);
    // Only the relative velocity matters: a at +1, b at -3.
    const auto s = ccd::aabb_sweep(unit, Vec3(1, 0, 0), b, Vec3(-3, 0, 0));
    CHECK(s.status == AabbSweepStatus::Hit);
    CHECK(s.t_first == 0.5);
    CHECK(s.t_last == 1.0);
    // Swapped roles give the same interval.
    const auto w = ccd::aabb_sweep(b, Vec3(-3, 0, 0), unit, Vec3(1, 0, 0));
    CHECK(w.t_first == 0.5);
    CHECK(w.t_last == 1.0);
  }
  SECTION("passing through: [0.2, 0.4]; a longer horizon does not change it") {
    const Aabb b{Vec3(3, 0.5, 0.5), Vec3(4, 0.75, 0.75)};
    for (double h : {1.0, 2.0, inf}) {
      const auto r = ccd::aabb_sweep(unit, still, b, Vec3(-10, 0, 0), h);
      REQUIRE(r.status == AabbSweepStatus::Hit);
      CHECK(r.t_first == 0.2);  // -2 / -10, correctly rounded
      CHECK(r.t_last == 0.4);   // -4 / -10
    }
  }
  SECTION("diagonal: x interval [0.2,0.4], y interval [0.5,1] are disjoint: miss") {
    const Aabb b{Vec3(3, 3, 0), Vec3(4, 4, 1)};
    const auto r = ccd::aabb_sweep(unit, still, b, Vec3(-10, -4, 0));
    CHECK(r.status == AabbSweepStatus::Miss);
    CHECK(r.t_first == inf);
    CHECK(r.t_last == -inf);
  }
  SECTION("overlapping at t = 0 and separating: [0, 0.5]") {
    const Aabb b{Vec3(0.5, 0, 0), Vec3(1.5, 1, 1)};
    const auto r = ccd::aabb_sweep(unit, still, b, Vec3(1, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Overlapping);
    CHECK(r.t_first == 0.0);
    CHECK(r.t_last == 0.5);  // (1 - 0.5) / 1
  }
  SECTION("negative coordinates") {
    // a = [-3,-2] x [-1,0] x [-5,-4] still; b = [-7,-6] x [-1,0] x [-5,-4] moving +8 in x:
    // first = (a.lo - b.hi) / 8 = (-3 + 6) / 8, last = (a.hi - b.lo) / 8 = (-2 + 7) / 8.
    const Aabb a{Vec3(-3, -1, -5), Vec3(-2, 0, -4)};
    const Aabb b{Vec3(-7, -1, -5), Vec3(-6, 0, -4)};
    const auto r = ccd::aabb_sweep(a, Vec3(0, 0, 0), b, Vec3(8, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 0.375);
    CHECK(r.t_last == 0.625);
  }
}

TEST_CASE("aabb_sweep degenerate cases", "[queries][aabb_sweep]") {
  const Vec3 still = Vec3::Zero();
  SECTION("boxes touching exactly: at rest, at the end of the step, corner to corner") {
    // Face contact at rest: overlapping over the whole step.
    auto r = ccd::aabb_sweep(unit, still, Aabb{Vec3(1, 0, 0), Vec3(2, 1, 1)}, still);
    REQUIRE(r.status == AabbSweepStatus::Overlapping);
    CHECK(r.t_first == 0.0);
    CHECK(r.t_last == 1.0);
    // Reaches a's face exactly at t = h = 1: a single instant, still contact.
    r = ccd::aabb_sweep(unit, still, Aabb{Vec3(2, 0, 0), Vec3(3, 1, 1)}, Vec3(-1, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 1.0);
    CHECK(r.t_last == 1.0);
    r = ccd::aabb_sweep(unit, still, Aabb{Vec3(2, 0, 0), Vec3(3, 1, 1)}, Vec3(-1, 0, 0), 0.875);
    CHECK(r.status == AabbSweepStatus::Miss);
    // Corner to corner: x overlaps on [0.2,0.4], y on [0.4,0.8]: touching at t = 0.4 only.
    r = ccd::aabb_sweep(unit, still, Aabb{Vec3(3, 3, 0), Vec3(4, 4, 1)}, Vec3(-10, -5, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 0.4);
    CHECK(r.t_last == 0.4);
    // Touching at t = 0 and moving apart: contact at the instant t = 0.
    r = ccd::aabb_sweep(unit, still, Aabb{Vec3(1, 0, 0), Vec3(2, 1, 1)}, Vec3(1, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Overlapping);
    CHECK(r.t_first == 0.0);
    CHECK(r.t_last == 0.0);
  }
  SECTION("zero velocity axis, separated: no contact (the published-code bug)") {
    // Moving in x straight through a's x range, but 1 apart in y with v_y = 0.
    const Aabb b{Vec3(3, 2, 0), Vec3(4, 3, 1)};
    auto r = ccd::aabb_sweep(unit, still, b, Vec3(-10, 0, 0));
    CHECK(r.status == AabbSweepStatus::Miss);
    // Same velocity for both boxes: nothing moves relatively, separated: miss.
    r = ccd::aabb_sweep(unit, Vec3(5, 5, 5), Aabb{Vec3(3, 0, 0), Vec3(4, 1, 1)}, Vec3(5, 5, 5));
    CHECK(r.status == AabbSweepStatus::Miss);
    // -0.0 is a zero velocity too.
    r = ccd::aabb_sweep(unit, still, b, Vec3(-10, -0.0, 0));
    CHECK(r.status == AabbSweepStatus::Miss);
  }
  SECTION("zero velocity axis, overlapping (or touching): that axis never limits") {
    auto r = ccd::aabb_sweep(unit, still, Aabb{Vec3(3, 1, 0), Vec3(4, 2, 1)}, Vec3(-10, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 0.2);
    CHECK(r.t_last == 0.4);
    // All velocities zero, overlapping: the whole step.
    r = ccd::aabb_sweep(unit, still, Aabb{Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2)}, still, 3.0);
    REQUIRE(r.status == AabbSweepStatus::Overlapping);
    CHECK(r.t_first == 0.0);
    CHECK(r.t_last == 3.0);
  }
  SECTION("zero-size boxes (points) and a zero-length step") {
    const Aabb p{Vec3(2, 0.5, 0.5), Vec3(2, 0.5, 0.5)};
    auto r = ccd::aabb_sweep(unit, still, p, Vec3(-2, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 0.5);
    CHECK(r.t_last == 1.0);
    r = ccd::aabb_sweep(unit, still, p, Vec3(-2, 0, 0), 0.0);
    CHECK(r.status == AabbSweepStatus::Miss);
    r = ccd::aabb_sweep(unit, still, unit, Vec3(-2, 0, 0), 0.0);
    CHECK(r.status == AabbSweepStatus::Overlapping);
    CHECK(r.t_last == 0.0);
  }
  SECTION("far from the origin (~1e6), dyadic coordinates: exact") {
    const Vec3 s(1e6, -1e6, 1e6);
    const Aabb a{unit.lo + s, unit.hi + s};
    const Aabb b{Vec3(3, 0.5, 0.5) + s, Vec3(4, 0.75, 0.75) + s};
    const auto r = ccd::aabb_sweep(a, still, b, Vec3(-10, 0, 0));
    REQUIRE(r.status == AabbSweepStatus::Hit);
    CHECK(r.t_first == 0.2);
    CHECK(r.t_last == 0.4);
  }
  SECTION("invalid input: degenerate") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Aabb inverted{Vec3(1, 0, 0), Vec3(0, 1, 1)};
    CHECK(ccd::aabb_sweep(unit, still, inverted, still).status == AabbSweepStatus::Degenerate);
    CHECK(ccd::aabb_sweep(unit, still, unit, still, -1.0).status == AabbSweepStatus::Degenerate);
    CHECK(ccd::aabb_sweep(unit, still, unit, still, nan).status == AabbSweepStatus::Degenerate);
    CHECK(ccd::aabb_sweep(unit, Vec3(nan, 0, 0), unit, still).status == AabbSweepStatus::Degenerate);
    CHECK(ccd::aabb_sweep(Aabb{Vec3(nan, 0, 0), Vec3(1, 1, 1)}, still, unit, still).status ==
          AabbSweepStatus::Degenerate);
  }
}

TEST_CASE("aabb_sweep equals brute force over exact sample times", "[queries][aabb_sweep]") {
  // Integer boxes and velocities with |v_i| <= 8: every interval end is a multiple of
  // 1/840 (840 = lcm(1..8)), and "closed overlap at t = k/840" is exact integer arithmetic
  // after scaling by 840. Brute force gives the exact contact set {k : k/840 in it};
  // the sweep's t_first, t_last are correctly rounded quotients of the same rationals, so
  // they must equal k_first/840.0, k_last/840.0 bit for bit.
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> C(-6, 6), V(-4, 4), L(0, 8);
  int hits = 0, misses = 0, still_axes = 0;
  for (int n = 0; n < 5000; ++n) {
    std::array<long, 3> alo, ahi, blo, bhi, v;
    Aabb a, b;
    Vec3 va, vb;
    for (int i = 0; i < 3; ++i) {
      alo[i] = C(rng);
      ahi[i] = alo[i] + L(rng);
      blo[i] = C(rng);
      bhi[i] = blo[i] + L(rng);
      const int ua = V(rng), ub = V(rng);
      v[i] = ub - ua;
      still_axes += v[i] == 0;
      a.lo[i] = static_cast<double>(alo[i]);
      a.hi[i] = static_cast<double>(ahi[i]);
      b.lo[i] = static_cast<double>(blo[i]);
      b.hi[i] = static_cast<double>(bhi[i]);
      va[i] = ua;
      vb[i] = ub;
    }
    long k_first = -1, k_last = -1;
    for (long k = 0; k <= 840; ++k) {
      bool overlap = true;
      for (int i = 0; i < 3; ++i) {
        overlap =
            overlap && 840 * blo[i] + v[i] * k <= 840 * ahi[i] && 840 * alo[i] <= 840 * bhi[i] + v[i] * k;
      }
      if (overlap) {
        if (k_first < 0) k_first = k;
        REQUIRE(k_last == (k_first == k ? -1 : k - 1));  // the contact set is an interval
        k_last = k;
      }
    }
    const auto r = ccd::aabb_sweep(a, va, b, vb);
    INFO("case " << n);
    if (k_first < 0) {
      ++misses;
      CHECK(r.status == AabbSweepStatus::Miss);
      continue;
    }
    ++hits;
    CHECK(r.status == (k_first == 0 ? AabbSweepStatus::Overlapping : AabbSweepStatus::Hit));
    CHECK(r.t_first == static_cast<double>(k_first) / 840.0);
    CHECK(r.t_last == static_cast<double>(k_last) / 840.0);
  }
  CHECK(hits > 500);
  CHECK(misses > 500);
  CHECK(still_axes > 1000);
}

}  // namespace ccd_queries_aabb_sweep_test
