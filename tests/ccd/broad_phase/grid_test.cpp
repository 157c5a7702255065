// The threaded uniform grid (GridOptions::threads > 1) against the serial one, which
// registry_test.cpp compares with brute force, and against the published peer-scene
// table. Threads split work only in pieces of >= 16,384 bodies (cell_grid.hpp), so the
// inputs here have 40,000 to 100,000 bodies to run on 2 to 6 threads; the claim tested is
// stronger than "same set": the same pairs in the same order as with one thread. Both
// neighbour scans are covered: the occupancy bitmap (dense levels) and the cursors (very
// sparse levels, more than 2^26 cells).
#include <ccd/broad_phase/brute_force.hpp>
#include <ccd/broad_phase/grid.hpp>
#include <ccd/broad_phase/hgrid.hpp>
#include <benchmarks/support/peer_scene.hpp>
#include <ccd/broad_phase/sap.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

namespace ccd_broad_phase_grid_test {

using ccd::Aabb;
using ccd::BodyPair;
using ccd::Vec3;

namespace {

std::vector<BodyPair> pairs_of(ccd::BroadPhase& bp, const std::vector<Aabb>& boxes) {
  std::vector<BodyPair> out{{7, 3}};  // stale content: find_pairs must clear it
  bp.find_pairs(boxes, out);
  return out;
}

// Cubes of half-size in [0.2, 1] in a box of side `side`; `side` sets the density.
std::vector<Aabb> gas(std::size_t n, double side, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> pos(0, side), half(0.2, 1.0);
  std::vector<Aabb> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c(pos(gen), pos(gen), pos(gen));
    const Vec3 h(half(gen), half(gen), half(gen));
    out.push_back({c - h, c + h});
  }
  return out;
}

// Threaded grid equals the serial grid pair for pair, in order; the set also equals sap's.
void check_threads(const std::vector<Aabb>& boxes, unsigned threads) {
  ccd::UniformGrid serial;
  ccd::UniformGrid threaded(ccd::GridOptions{.threads = threads});
  const std::vector<BodyPair> want = pairs_of(serial, boxes);
  const std::vector<BodyPair> got = pairs_of(threaded, boxes);
  REQUIRE(got.size() == want.size());
  REQUIRE(got == want);
  REQUIRE(threaded.stats().box_tests == serial.stats().box_tests);
  ccd::SweepAndPrune sap;
  std::vector<BodyPair> other = pairs_of(sap, boxes), sorted = got;
  std::sort(other.begin(), other.end());
  std::sort(sorted.begin(), sorted.end());
  REQUIRE(sorted == other);
}

}  // namespace

TEST_CASE("threaded grid reports the serial grid's pairs in the same order", "[broad_phase][grid]") {
  SECTION("sparse gas, 2 threads") { check_threads(gas(40000, 150.0, 3), 2); }
  SECTION("dense gas (many bodies per cell, ranges split between busy cells), 2 and 3 threads") {
    const std::vector<Aabb> boxes = gas(50000, 40.0, 4);
    check_threads(boxes, 2);
    check_threads(boxes, 3);
  }
  SECTION("more threads than pieces of 16,384 bodies: capped, same result") { check_threads(gas(40000, 150.0, 5), 16); }
  SECTION("7 threads (more than most machines' cores), sparse and dense gas") {
    check_threads(gas(120000, 200.0, 8), 7);  // 120,000 bodies: 7 pieces of >= 16,384
    check_threads(gas(120000, 60.0, 9), 7);
  }
  SECTION("equal coordinates: touching unit cubes on a lattice, 4 threads") {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j)
        for (int k = 0; k < 42; ++k) {
          const Vec3 lo(i, j, k);
          boxes.push_back({lo, lo + Vec3::Constant(1.0)});
        }
    check_threads(boxes, 4);
  }
  SECTION("far from the origin: offset 1e6, 2 threads") {
    std::vector<Aabb> boxes = gas(40000, 150.0, 6);
    for (Aabb& b : boxes) {
      b.lo.array() += 1e6;
      b.hi.array() += 1e6;
    }
    check_threads(boxes, 2);
  }
  SECTION("threads = 0 means serial") { check_threads(gas(40000, 150.0, 7), 0); }
  SECTION("very sparse (more than 2^26 cells: cursor scan instead of the occupancy bitmap), 2 threads") {
    // 1500^3 cells of side <= 2 over [0, 3000]^3; a dense cluster adds pairs to find.
    std::vector<Aabb> boxes = gas(38000, 3000.0, 8);
    const std::vector<Aabb> cluster = gas(2000, 20.0, 9);
    boxes.insert(boxes.end(), cluster.begin(), cluster.end());
    check_threads(boxes, 2);
  }
}

TEST_CASE("threaded grid: N = 100000 peer scene frames 0 and 22 match the published table",
          "[broad_phase][grid][peer]") {
  const ccdlab::bench::PeerSceneReference* ref = nullptr;
  for (const auto& r : ccdlab::bench::peer_scene_references())
    if (r.n == 100000) ref = &r;
  REQUIRE(ref != nullptr);
  ccdlab::bench::PeerScene scene(100000, 1);
  std::vector<Aabb> boxes;
  std::vector<BodyPair> pairs;
  ccd::UniformGrid grid(ccd::GridOptions{.threads = 2});
  scene.boxes(boxes);
  grid.find_pairs(boxes, pairs);
  CHECK(pairs.size() == ref->pairs_0);
  CHECK(ccdlab::bench::peer_pair_checksum(pairs) == ref->checksum_0);
  for (int f = 1; f <= 22; ++f) scene.step();
  scene.boxes(boxes);
  grid.find_pairs(boxes, pairs);
  CHECK(pairs.size() == ref->pairs_22);
  CHECK(ccdlab::bench::peer_pair_checksum(pairs) == ref->checksum_22);
}

namespace {

// grid and hgrid (one engine, cell_grid.hpp) against brute force, as sets.
void check_exact(const std::vector<Aabb>& boxes, std::size_t expected_pairs) {
  ccd::BruteForce brute;
  std::vector<BodyPair> want = pairs_of(brute, boxes);
  std::sort(want.begin(), want.end());
  REQUIRE(want.size() == expected_pairs);
  ccd::UniformGrid grid;
  ccd::HierarchicalGrid hgrid;
  for (ccd::BroadPhase* bp : {static_cast<ccd::BroadPhase*>(&grid), static_cast<ccd::BroadPhase*>(&hgrid)}) {
    std::vector<BodyPair> got = pairs_of(*bp, boxes);
    std::sort(got.begin(), got.end());
    CHECK(got == want);
  }
}

// A row of `n` boxes along `axis`, each of length `len` starting at base + k (len + gap_k),
// gap_k = 0 for even k (touching: a pair) and `gap` for odd k (apart: no pair), plus a
// second, unit-size box over each (so the boxes have two sizes, and hgrid two levels).
std::vector<Aabb> touching_row(int axis, int n, double base, double len, double gap) {
  std::vector<Aabb> out;
  double x = base;
  for (int k = 0; k < n; ++k) {
    Aabb b{Vec3::Constant(base), Vec3::Constant(base + len)};
    b.lo[axis] = x;
    b.hi[axis] = x + len;
    out.push_back(b);
    x += len + (k % 2 == 0 ? 0.0 : gap);
  }
  return out;
}

}  // namespace

TEST_CASE("grid and hgrid separate touching boxes from boxes one tiny gap apart at any scale",
          "[broad_phase][grid]") {
  // Dyadic bounds chosen so that every sum below is exact: touching boxes share a bound
  // bit for bit, apart ones differ by the gap (far below the cell size, and below single
  // precision: a cell index or a float filter rounding them together must not decide).
  // Rows of 64 boxes, 32 touching junctions (k even) and 31 gaps: 32 pairs per row.
  SECTION("touching at 1 + 2^-40, apart by 2^-40, on each axis") {
    for (int axis = 0; axis < 3; ++axis) check_exact(touching_row(axis, 64, 1.0, 1.0 + 0x1p-40, 0x1p-40), 32);
  }
  SECTION("far from the origin: base 2^40 (float step 2^17), lengths 1 + 2^-12, gaps 2^-12") {
    check_exact(touching_row(0, 64, 0x1p40, 1.0 + 0x1p-12, 0x1p-12), 32);
  }
  SECTION("beyond the float range: base 2^130 and -2^130") {
    check_exact(touching_row(1, 64, 0x1p130, 0x1p80, 0x1p78), 32);
    check_exact(touching_row(2, 64, -0x1p130, 0x1p80, 0x1p78), 32);
  }
  SECTION("below the float range: lengths 2^-1000 + 2^-1040, gaps 2^-1040 (all round to 0)") {
    check_exact(touching_row(0, 64, 0.0, 0x1p-1000 + 0x1p-1040, 0x1p-1040), 32);
  }
  SECTION("sign change: boxes touching at 0 from both sides, and at -0.0") {
    std::vector<Aabb> boxes = {{Vec3(-1, -1, -1), Vec3(0, 0, 0)}, {Vec3(-0.0, -1, -1), Vec3(1, 0, 0)},
                               {Vec3(0x1p-60, 0x1p-60, 0x1p-60), Vec3(1, 1, 1)}};
    // {0,1} touch at x = 0 (-0.0 == 0); box 2 starts 2^-60 beyond both on every axis.
    check_exact(boxes, 1);
  }
  SECTION("mixed sizes with 2^-40 gaps: hgrid's cross-level scan on two levels") {
    std::vector<Aabb> boxes = touching_row(0, 64, 3.0, 1.0 + 0x1p-40, 0x1p-40);
    // A large box ending exactly where the row starts (touching box 0 only) and one ending
    // 2^-40 before it (touching nothing); both share the row's y and z range.
    boxes.push_back({Vec3(3.0 - 40.0, 3.0, 3.0), Vec3(3.0, 4.0, 4.0)});
    boxes.push_back({Vec3(3.0 - 40.0, 3.0 - 50.0, 3.0 - 50.0), Vec3(3.0 - 0x1p-40, 3.0 - 0x1p-40, 3.0 - 0x1p-40)});
    check_exact(boxes, 33);
  }
}

}  // namespace ccd_broad_phase_grid_test
