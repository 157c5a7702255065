// The hierarchy's traversal and candidate generation are tuned for speed; what they return
// must not change. The digests below were recorded with the straightforward traversal
// (triangle and edge boxes merged per leaf pair, std::sort of the candidates) on a sheet
// folding over itself, for `bvh` and `bvh_cones`.
#include <cloth/cull/bvh_culler.hpp>
#include <cloth/cull/triangle_bvh.hpp>
#include <cloth/sim/cloth_scene.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>

using namespace ccd::cloth;
using ccd::Vec3;

namespace {

// An S-fold of an n x n grid sheet, frame f of 16: x = u - s u^3 with s growing from 0 to
// 3 folds the sheet over itself (x stops being monotone in u at s = 1/3); z separates the
// layers a little. Basic arithmetic only, so the frames are bit-identical in every build.
std::vector<Vec3> fold_frame(int n, int f) {
  std::vector<Vec3> x;
  const double s = 3.0 * f / 16.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2.0 * i / (n - 1) - 1.0, v = 1.0 * j / (n - 1);
      x.emplace_back(u - s * u * u * u, v + u * v / 8.0, u * u / 8.0 + s * u / 16.0);
    }
  return x;
}

}  // namespace

TEST_CASE("bvh and bvh_cones return the recorded candidates on a folding sheet", "[cloth][cull]") {
  const ClothScene scene = builtin_cloth_scene("pile", 12);
  const ClothMesh mesh = make_grid_mesh(scene);
  for (const auto& [cones, count, digest] :
       {std::tuple{false, 48485ull, 0x5b1fd8142b6156fdull}, std::tuple{true, 41374ull, 0x631e59a9d5347cceull}}) {
    INFO((cones ? "bvh_cones" : "bvh"));
    BvhCuller culler(cones);
    std::uint64_t h = 1469598103934665603ull, n = 0;  // FNV-1a over (kind, a, b) in order
    for (int f = 0; f < 16; ++f)
      for (const Candidate& c : culler.cull(mesh, fold_frame(12, f), fold_frame(12, f + 1), 0.05)) {
        for (const std::uint64_t v : {static_cast<std::uint64_t>(c.kind), std::uint64_t{c.a}, std::uint64_t{c.b}}) {
          h ^= v;
          h *= 1099511628211ull;
        }
        ++n;
      }
    CHECK(n == count);
    CHECK(h == digest);
  }
}

TEST_CASE("sort_candidates orders as std::sort does", "[cloth][cull]") {
  std::mt19937_64 rng(1617);
  for (const std::uint32_t range : {3u, 1000u, 70000u, 0xffffffffu}) {  // the last falls back to std::sort
    INFO("range " << range);
    std::uniform_int_distribution<std::uint32_t> idx(0, range), kind(0, 1);
    std::vector<Candidate> c;
    for (int i = 0; i < 5000; ++i)
      c.push_back(Candidate{kind(rng) ? PrimitivePair::EdgeEdge : PrimitivePair::VertexFace, idx(rng), idx(rng)});
    c.push_back(c.front());  // a duplicate keeps its place in the order
    std::vector<Candidate> expected = c;
    std::sort(expected.begin(), expected.end());
    sort_candidates(c);
    CHECK(c == expected);
  }
}
