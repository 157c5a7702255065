// bvh_cones at a separation d > 0 on adversarial sheets: every patch below faces one way
// (narrow normal cones), yet non-adjacent primitives of it come within d. A cone test alone
// skips those patches' self-tests and drops the pairs; the flatness certificate
// (cloth/cull/triangle_bvh.hpp) must keep every pair that the exact truth (certified
// decision, then the exact rational reference) finds within d, and may drop only pairs
// proved apart.
//
// The hierarchy's traversal and candidate generation are tuned for speed; what they return
// must not change. The digests below were recorded with the straightforward traversal
// (triangle and edge boxes merged per leaf pair, std::sort of the candidates) on a sheet
// folding over itself, for `bvh` and `bvh_cones`
// (`bvh_cones` with its flatness certificate).
#include <cloth/cull/bvh_culler.hpp>
#include <cloth/cull/triangle_bvh.hpp>
#include <cloth/sim/cloth_scene.hpp>
#include <cloth/truth/mesh_truth.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace cloth_cull_triangle_bvh_test {

using namespace ccd::cloth;
using ccd::Vec3;

namespace {

// A grid mesh of nx x ny particles with its chart (the indices), positions from `at(i, j)`.
template <class F>
std::pair<ClothMesh, std::vector<Vec3>> grid(int nx, int ny, F at) {
  ClothScene s = builtin_cloth_scene("drape", 4);
  s.nx = nx;
  s.ny = ny;
  const ClothMesh mesh = make_grid_mesh(s);
  std::vector<Vec3> x(static_cast<std::size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) x[static_cast<std::size_t>(i + nx * j)] = at(i, j);
  return {mesh, x};
}

struct Outcome {
  std::size_t contacts = 0, kept = 0, bvh = 0;
  BvhStats stats;
};

// bvh_cones on x0 -> x1 at separation d: no truth contact dropped.
Outcome check_no_contact_dropped(const ClothMesh& mesh, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                 double d) {
  TriangleBvh tree(mesh, x0);
  tree.refit(x0, x1, d / 2);
  Outcome o;
  const std::vector<Candidate> kept = tree.self_candidates(true, &o.stats);
  const std::vector<Candidate> all = tree.self_candidates(false);
  const std::vector<Candidate> truth = contacts_among(mesh, all, x0, x1, d);
  // bvh keeps every pair whose boxes overlap; pairs within d have overlapping boxes, so the
  // truth among bvh's pairs is the truth among all pairs.
  for (const Candidate& c : truth) {
    INFO("dropped contact " << to_string(c.kind) << " " << c.a << " " << c.b);
    CHECK(std::binary_search(kept.begin(), kept.end(), c));
  }
  CHECK(std::includes(all.begin(), all.end(), kept.begin(), kept.end()));
  o.contacts = truth.size();
  o.kept = kept.size();
  o.bvh = all.size();
  return o;
}


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

TEST_CASE("bvh_cones keeps the two layers of a fold closer than the separation", "[cloth][cull]") {
  // A sheet folded back over its end: the lower layer at z = 0 runs along +x, the upper one
  // at height h runs back along -x over the last 4 columns, joined by a vertical column of
  // triangles. Spacing 1/8, d = 1/16: the layers (h = 1/32) are within d without
  // intersecting. Where the lower layer is alone the patches are flat (narrow cone, proved
  // flat: their self-tests are skipped); nodes holding both layers have wide cones.
  // Continuous: the upper layer comes down from 3/16 (beyond d) to h. Dyadic, near the
  // origin and 2^20 from it.
  const double s = 0.125, d = 0.0625;
  for (const double shift : {0.0, 0x1p20})
    for (const double h0 : {0.03125, 0.1875}) {
      INFO("shift " << shift << ", upper layer from " << h0);
      const int nx = 20, ny = 5, m = 14;
      auto at = [&](double h) {
        return [=](int i, int j) {
          const bool upper = i > m;
          return Vec3(shift + (upper ? 2 * m + 1 - i : i) * s, shift + j * s, shift + (upper ? h : 0.0));
        };
      };
      const auto [mesh, x0] = grid(nx, ny, at(h0));
      const auto x1 = grid(nx, ny, at(0.03125)).second;
      const Outcome o = check_no_contact_dropped(mesh, x0, x1, d);
      CHECK(o.contacts > 0);               // the layers are within d
      CHECK(o.stats.cone_culled > 0);      // flat layers' self-tests are skipped
      CHECK(o.kept < o.bvh);               // and that drops pairs (proved apart)
    }
}

TEST_CASE("bvh_cones keeps the turns of a flat ramp closer than the separation", "[cloth][cull]") {
  // A helicoidal ramp (a parking garage's): 1.25 turns, pitch 0.03, radius 1 to 1.25.
  // Its normals are all within a few degrees of +z, so the whole ramp has a narrow cone,
  // yet its turns lie 0.03 < d = 0.05 apart: the old cone rule dropped every pair. The
  // certificate fails where a patch wraps around (not affine in projection) and holds on
  // smaller pieces.
  const double d = 0.05;
  auto ramp = [](double pitch) {
    return [=](int i, int j) {
      const double turn = 1.25 * i / 47.0, a = 2 * std::numbers::pi * turn, r = 1.0 + 0.125 * j;
      return Vec3(r * std::cos(a), r * std::sin(a), pitch * turn);
    };
  };
  const auto [mesh, x0] = grid(48, 3, ramp(0.03));
  const auto x1 = grid(48, 3, ramp(0.02)).second;
  for (const bool continuous : {false, true}) {
    INFO((continuous ? "continuous" : "discrete"));
    const Outcome o = check_no_contact_dropped(mesh, x0, continuous ? x1 : x0, d);
    CHECK(o.contacts > 0);
    CHECK(o.stats.cone_rejected > 0);  // narrow cones that could not be proved flat
    CHECK(o.stats.cone_culled > 0);    // smaller pieces that were
  }
}

TEST_CASE("bvh_cones keeps the pairs of a sheet compressed below the separation", "[cloth][cull]") {
  // A flat sheet (cone half-angle 0) whose columns are 2^-6 apart, with d = 2^-5: vertices
  // two columns apart are exactly at d (touching counts). No patch can be proved flat,
  // so bvh_cones keeps everything bvh keeps.
  const double d = 0x1p-5;
  const auto [mesh, x] = grid(10, 6, [](int i, int j) { return Vec3(i * 0x1p-6, j * 0.25, 0.0); });
  const Outcome o = check_no_contact_dropped(mesh, x, x, d);
  CHECK(o.contacts > 0);
  CHECK(o.kept == o.bvh);
  CHECK(o.stats.cone_culled == 0);
  CHECK(o.stats.cone_rejected > 0);
}

TEST_CASE("bvh_cones skips nothing without a chart", "[cloth][cull]") {
  const auto [mesh0, x] = grid(8, 8, [](int i, int j) { return Vec3(i * 0.125, j * 0.125, 0.0); });
  ClothMesh mesh = mesh0;
  mesh.chart.clear();
  TriangleBvh tree(mesh, x);
  tree.refit(x, x, 0.01);
  BvhStats stats;
  CHECK(tree.self_candidates(true, &stats) == tree.self_candidates(false));
  CHECK(stats.cone_culled == 0);
}

TEST_CASE("bvh and bvh_cones return the recorded candidates on a folding sheet", "[cloth][cull]") {
  const ClothScene scene = builtin_cloth_scene("pile", 12);
  const ClothMesh mesh = make_grid_mesh(scene);
  for (const auto& [cones, count, digest] :
       {std::tuple{false, 48485ull, 0x5b1fd8142b6156fdull}, std::tuple{true, 47972ull, 0x4f96148a17a91329ull}}) {
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

}  // namespace cloth_cull_triangle_bvh_test
