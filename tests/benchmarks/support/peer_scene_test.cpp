// The reproduction of the shared peer scene (benchmarks/support/peer_scene.hpp) against its
// published pair counts and pair checksums, for N = 1000 (every frame 0..22) and 10000
// (frames 0 and 22); the benchmark re-checks 100,000 and 1,000,000 at startup.
//
// The published STATE hashes are not asserted: FNV-1a 64 over p.x p.y p.z v.x v.y v.z r
// as described does not reproduce them (nor does any order of those 7 fields, FNV-1,
// big-endian bytes, or a size prefix), while every pair count and pair-set checksum does,
// so the doubles are right and the hash's description is not. docs/broad_phases.md.
#include <benchmarks/support/peer_scene.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

namespace benchmarks_support_peer_scene_test {

namespace {

const ccdlab::bench::PeerSceneReference& reference(std::size_t n) {
  for (const auto& r : ccdlab::bench::peer_scene_references())
    if (r.n == n) return r;
  FAIL("no reference for N = " << n);
  throw;
}

}  // namespace

TEST_CASE("the peer scene's side length follows its formula", "[broad_phase][peer]") {
  // The tabulated L values are cbrt(N * per_sphere) correctly rounded; libm's cbrt may
  // differ by an ulp, hence the 2-ulp tolerance.
  for (const auto& r : ccdlab::bench::peer_scene_references()) {
    const double per_sphere = 4.0 / 3.0 * 3.141592653589793 * 1.25 / 0.02;
    CHECK(ccdlab::bench::peer_scene_side(r.n) ==
          Approx(std::cbrt(static_cast<double>(r.n) * per_sphere)).epsilon(4 * std::numeric_limits<double>::epsilon()));
  }
}

TEST_CASE("the peer pair hash is splitmix64's finaliser", "[broad_phase][peer]") {
  // splitmix64(0) with seed-increment applied once: its well-known first output.
  CHECK(ccdlab::bench::peer_pair_hash(0, 0) == 0xe220a8397b1dcdafULL);
  CHECK(ccdlab::bench::peer_pair_hash(3, 9) == ccdlab::bench::peer_pair_hash(9, 3));
}

TEST_CASE("N = 1000: every frame's pairs match the published counts, for every method", "[broad_phase][peer]") {
  // Pairs in frames 0 ... 22 as published (seed 1).
  const std::uint64_t counts[23] = {121, 123, 126, 120, 119, 119, 117, 118, 118, 122, 128, 128,
                                    131, 134, 134, 133, 136, 133, 135, 137, 140, 146, 151};
  const auto& ref = reference(1000);
  const auto& info = GENERATE(from_range(ccd::broad_phase_registry().begin(), ccd::broad_phase_registry().end()));
  CAPTURE(std::string(info.name));
  auto bp = info.make();
  ccdlab::bench::PeerScene scene(1000, 1);
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs;
  for (int f = 0; f <= 22; ++f) {
    CAPTURE(f);
    if (f > 0) scene.step();
    scene.boxes(boxes);
    bp->find_pairs(boxes, pairs);
    CHECK(pairs.size() == counts[f]);
    if (f == 0) CHECK(ccdlab::bench::peer_pair_checksum(pairs) == ref.checksum_0);
    if (f == 22) CHECK(ccdlab::bench::peer_pair_checksum(pairs) == ref.checksum_22);
  }
}

TEST_CASE("N = 10000: frame 0 / 22 pairs match the published table", "[broad_phase][peer]") {
  const auto& ref = reference(10000);
  ccdlab::bench::PeerScene scene(10000, 1);
  std::vector<ccd::Aabb> boxes0, boxes22;
  scene.boxes(boxes0);
  for (int f = 1; f <= 22; ++f) scene.step();
  scene.boxes(boxes22);
  std::vector<ccd::BodyPair> pairs;
  for (const auto& info : ccd::broad_phase_registry()) {
    if (info.name == "brute") continue;  // 5e7 tests per frame: too slow under sanitizers
    CAPTURE(std::string(info.name));
    auto bp = info.make();
    bp->find_pairs(boxes0, pairs);
    CHECK(pairs.size() == ref.pairs_0);
    CHECK(ccdlab::bench::peer_pair_checksum(pairs) == ref.checksum_0);
    bp->find_pairs(boxes22, pairs);
    CHECK(pairs.size() == ref.pairs_22);
    CHECK(ccdlab::bench::peer_pair_checksum(pairs) == ref.checksum_22);
  }
}

}  // namespace benchmarks_support_peer_scene_test
