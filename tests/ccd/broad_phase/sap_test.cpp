// `sap` (I-COLLIDE sweep and prune) beyond the registry's brute-force comparison: the
// persistent pair set over long frame sequences with exact touching, the start-before-end
// tie rule along different histories, swap counts for a complete reversal and for small
// motions. Coordinates are dyadic (multiples of 1/8 within 2^10) so every sum is exact
// and exact touching really happens.
#include <ccd/broad_phase/brute_force.hpp>
#include <ccd/broad_phase/sap.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <random>

namespace ccd_broad_phase_sap_test {

using ccd::Aabb;
using ccd::BodyPair;
using ccd::Vec3;

namespace {

std::vector<BodyPair> run(ccd::BroadPhase& bp, const std::vector<Aabb>& boxes) {
  std::vector<BodyPair> out;
  bp.find_pairs(boxes, out);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<BodyPair> brute(const std::vector<Aabb>& boxes) {
  ccd::BruteForce b;
  return run(b, boxes);
}

// Pairs that touch exactly on some axis (hi of one == lo of the other) and overlap.
std::size_t touching_pairs(const std::vector<Aabb>& boxes, const std::vector<BodyPair>& pairs) {
  std::size_t count = 0;
  for (const BodyPair& p : pairs) {
    const Aabb &a = boxes[p.a], &b = boxes[p.b];
    bool touch = false;
    for (int ax = 0; ax < 3; ++ax) touch = touch || a.hi[ax] == b.lo[ax] || b.hi[ax] == a.lo[ax];
    count += touch ? 1 : 0;
  }
  return count;
}

}  // namespace

TEST_CASE("sap keeps an exact pair set over 200 frames of a moving gas", "[broad_phase][sap]") {
  // 400 boxes in [0, 24]^3, centres on the 1/8 grid, half extents in {1/2, 3/4, 1},
  // velocities in {-1/4, -1/8, 0, 1/8, 1/4} per axis, reflected at the walls: endpoints
  // become exactly equal (touching boxes) and separate again all the time.
  std::mt19937_64 gen(31);
  std::uniform_int_distribution<int> cell(8, 184), half(2, 4), vel(-2, 2);
  const std::size_t n = 400;
  std::vector<Vec3> c(n), h(n), v(n);
  for (std::size_t i = 0; i < n; ++i) {
    c[i] = Vec3(cell(gen), cell(gen), cell(gen)) / 8.0;
    h[i] = Vec3(half(gen), half(gen), half(gen)) / 4.0;
    v[i] = Vec3(vel(gen), vel(gen), vel(gen)) / 8.0;
  }
  ccd::SweepAndPrune sap;
  std::vector<Aabb> boxes(n);
  std::size_t touching = 0, became_separated = 0;
  std::vector<BodyPair> previous;
  for (int f = 0; f < 200; ++f) {
    CAPTURE(f);
    for (std::size_t i = 0; i < n; ++i) boxes[i] = {c[i] - h[i], c[i] + h[i]};
    const std::vector<BodyPair> got = run(sap, boxes);
    const std::vector<BodyPair> want = brute(boxes);
    REQUIRE(got == want);  // sorted, so this also rules out duplicates
    for (const BodyPair& p : got) REQUIRE(p.a < p.b);
    REQUIRE(sap.stats().rebuilt == (f == 0));  // the incremental path, not rebuilds
    touching += touching_pairs(boxes, got);
    for (const BodyPair& p : previous) became_separated += std::binary_search(got.begin(), got.end(), p) ? 0 : 1;
    previous = got;
    for (std::size_t i = 0; i < n; ++i) {
      for (int a = 0; a < 3; ++a)
        if ((c[i][a] <= 1 && v[i][a] < 0) || (c[i][a] >= 23 && v[i][a] > 0)) v[i][a] = -v[i][a];
      c[i] += v[i];
    }
  }
  // The sequence did exercise touching pairs and pairs separating again.
  CHECK(touching > 100);
  CHECK(became_separated > 100);
}

TEST_CASE("sap reports touching boxes whatever the history (ties: starts before ends)", "[broad_phase][sap]") {
  // Box A = [0, 1]^3 stays; box B (unit) ends touching A on one axis: B.lo = A.hi = 1 or
  // B.hi = A.lo = 0. It reaches that position from apart and from overlapping. A strict
  // swap rule (a start after an end at equal values) keeps the pair only when coming from
  // overlap; a rule that is not the sort key loses it coming from apart. Both must be
  // reported, and the pair must disappear again when B moves on.
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {1.0, -1.0}) {  // B on the + side (B.lo = 1) or - side (B.hi = 0)
      for (const double before : {2.0, 1.5, 0.5, 0.0}) {  // offsets: apart, apart, overlapping, coincident
        CAPTURE(axis, side, before);
        ccd::SweepAndPrune sap;
        const Aabb a{Vec3(0, 0, 0), Vec3(1, 1, 1)};
        auto b_at = [&](double offset) {
          Vec3 d = Vec3::Zero();
          d[axis] = side * offset;
          return Aabb{a.lo + d, a.hi + d};
        };
        // A third box far away keeps the count fixed and gives the lists a neighbour.
        const Aabb far{Vec3(10, 10, 10), Vec3(11, 11, 11)};
        const bool overlap_before = before <= 1.0;
        CHECK(run(sap, {a, b_at(before), far}).size() == (overlap_before ? 1u : 0u));
        const std::vector<BodyPair> touching = run(sap, {a, b_at(1.0), far});  // exactly touching
        REQUIRE_FALSE(sap.stats().rebuilt);
        REQUIRE(touching == std::vector<BodyPair>{{0, 1}});
        REQUIRE(run(sap, {a, b_at(1.0), far}).size() == 1u);   // stays, no motion
        REQUIRE(run(sap, {a, b_at(1.25), far}).empty());       // separated
        REQUIRE(run(sap, {a, b_at(1.0), far}).size() == 1u);   // touching again, from apart
      }
    }
  }
}

TEST_CASE("sap counts the swaps of a complete reversal or rebuilds", "[broad_phase][sap]") {
  // Unit boxes [i, i+1] x [0,1] x [0,1], i = 0..n-1 (neighbours touch), then body i at
  // x = n-1-i. On x every endpoint pair of bodies i < j inverts (4 swaps) except, for
  // neighbours j = i + 1, start/end (touching: the start stays first): 2 swaps. On y and
  // z all keys are equal: no swaps. Total 4 (C(n,2) - (n-1)) + 2 (n-1) = 2 (n-1)^2.
  const int n = 300;
  std::vector<Aabb> fwd, rev;
  for (int i = 0; i < n; ++i) {
    fwd.push_back({Vec3(i, 0, 0), Vec3(i + 1, 1, 1)});
    rev.push_back({Vec3(n - 1 - i, 0, 0), Vec3(n - i, 1, 1)});
  }
  SECTION("default budget: coherence lost, rebuilt") {
    ccd::SweepAndPrune sap;
    run(sap, fwd);
    REQUIRE(run(sap, rev) == brute(rev));
    CHECK(sap.stats().rebuilt);
    REQUIRE(run(sap, fwd) == brute(fwd));
    CHECK(sap.stats().rebuilt);
  }
  SECTION("unlimited budget: the insertion sort goes through") {
    ccd::SweepAndPrune sap(ccd::SapOptions{.swaps_per_endpoint = std::numeric_limits<std::uint32_t>::max()});
    run(sap, fwd);
    REQUIRE(run(sap, rev) == brute(rev));
    CHECK_FALSE(sap.stats().rebuilt);
    CHECK(sap.swaps() == 2u * (n - 1) * (n - 1));
    REQUIRE(run(sap, fwd) == brute(fwd));
    CHECK(sap.swaps() == 2u * (n - 1) * (n - 1));
    // The generic view of the same count: one counter, named "swaps".
    const ccd::BroadPhase& generic = sap;
    REQUIRE(generic.counters().size() == 1);
    CHECK(generic.counters()[0].name == "swaps");
    CHECK(generic.counters()[0].value == 2u * (n - 1) * (n - 1));
  }
}

TEST_CASE("sap swaps per frame follow the motion", "[broad_phase][sap]") {
  SECTION("no motion, rigid dyadic translation: zero swaps, zero box tests") {
    std::mt19937_64 gen(41);
    std::uniform_int_distribution<int> cell(0, 800), half(1, 8);
    std::vector<Aabb> boxes;
    for (int i = 0; i < 500; ++i) {
      const Vec3 c = Vec3(cell(gen), cell(gen), cell(gen)) / 8.0;
      boxes.push_back({c - Vec3::Constant(half(gen) / 8.0), c + Vec3::Constant(half(gen) / 8.0)});
    }
    ccd::SweepAndPrune sap;
    const std::vector<BodyPair> want = run(sap, boxes);
    REQUIRE(run(sap, boxes) == want);
    CHECK(sap.swaps() == 0u);
    CHECK(sap.stats().box_tests == 0u);
    for (Aabb& b : boxes) {  // + (3/8, -5/4, 7/2): exact, keeps every order and every tie
      b.lo += Vec3(0.375, -1.25, 3.5);
      b.hi += Vec3(0.375, -1.25, 3.5);
    }
    REQUIRE(run(sap, boxes) == want);
    CHECK(sap.swaps() == 0u);
    CHECK_FALSE(sap.stats().rebuilt);
  }
  SECTION("one body moving past k others: 4k swaps") {
    // Boxes [2i, 2i+1] on x, equal on y and z. Body 0 jumps to [2k + 1.25, 2k + 1.75]:
    // each of its two endpoints passes the 2k endpoints of bodies 1..k.
    const int n = 50;
    for (const int k : {1, 7, 30}) {
      CAPTURE(k);
      std::vector<Aabb> boxes;
      for (int i = 0; i < n; ++i) boxes.push_back({Vec3(2 * i, 0, 0), Vec3(2 * i + 1, 1, 1)});
      ccd::SweepAndPrune sap;
      run(sap, boxes);
      boxes[0] = {Vec3(2 * k + 1.25, 0, 0), Vec3(2 * k + 1.75, 1, 1)};
      REQUIRE(run(sap, boxes) == brute(boxes));
      CHECK_FALSE(sap.stats().rebuilt);
      CHECK(sap.swaps() == 4u * static_cast<std::uint64_t>(k));
    }
  }
  SECTION("small random motion of a gas: few swaps per body") {
    // Per axis 2n = 1200 endpoints over ~31.6: ~38 per unit length. Two endpoints of
    // different bodies move by a relative |d1 - d2| ~ 6.7e-4 on average (d uniform in
    // +-1e-3), so the expected swaps are ~ 1200 * 38 * 6.7e-4 / 2 ~ 15 per axis, ~46 per
    // frame (starts and ends of one body move together: no swap). The bound n / 4 = 150
    // leaves a 3x margin; counting scanned endpoints (6n) instead of swaps would fail.
    std::mt19937_64 gen(43);
    std::uniform_real_distribution<double> pos(0, 30), rad(0.2, 0.8), jitter(-1e-3, 1e-3);
    const std::size_t n = 600;
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i < n; ++i) boxes.push_back(Aabb::around(Vec3(pos(gen), pos(gen), pos(gen)), rad(gen)));
    ccd::SweepAndPrune sap;
    run(sap, boxes);
    for (int f = 0; f < 10; ++f) {
      for (Aabb& b : boxes) {
        const Vec3 d(jitter(gen), jitter(gen), jitter(gen));
        b.lo += d;
        b.hi += d;
      }
      REQUIRE(run(sap, boxes) == brute(boxes));
      CHECK_FALSE(sap.stats().rebuilt);
      CHECK(sap.swaps() < n / 4);
      CHECK(sap.swaps() > 0u);  // ~46 expected: the motion does reorder some endpoints
    }
  }
}

}  // namespace ccd_broad_phase_sap_test
