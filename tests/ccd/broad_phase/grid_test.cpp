// The threaded uniform grid (GridOptions::threads > 1) against the serial one, which
// registry_test.cpp compares with brute force, and against the published peer-scene
// table. Threads split work only in pieces of >= 16,384 bodies (cell_grid.hpp), so the
// inputs here have 40,000 to 100,000 bodies to run on 2 to 6 threads; the claim tested is
// stronger than "same set": the same pairs in the same order as with one thread. Both
// neighbour scans are covered: the occupancy bitmap (dense levels) and the cursors (very
// sparse levels, more than 2^26 cells).
#include <ccd/broad_phase/grid.hpp>
#include <benchmarks/support/peer_scene.hpp>
#include <ccd/broad_phase/sap.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

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
