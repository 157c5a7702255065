// Every culler against brute force on the cloth scenes: candidates are a subset of the
// brute-force pairs, and every brute-force pair a culler drops is proved contact-free
// over the check interval (the proof of a culler that may drop pairs, and a check of the
// others). The proof is the conservative kernel's Miss (a certified result: its rounding
// is bounded) or, when the kernel reports a possible contact, the exact rational CCD: at
// the separation for the conservative cullers (bvh_cones included), at separation 0 for
// sensors (it is not claimed conservative at a separation).
#include <cloth/cull/cullers.hpp>
#include <cloth/cull/triangle_bvh.hpp>
#include <cloth/cull/bvh_culler.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/sim/cloth_simulator.hpp>

#include <algorithm>
#include <random>
#include <catch2/catch.hpp>

namespace cloth_cull_cullers_test {

using namespace ccd::cloth;
using ccd::Vec3;

namespace {

struct Interval {
  std::string scene;
  int k;  // frames k -> k + stride
};

}  // namespace

TEST_CASE("cullers drop only pairs that are proved contact-free", "[cloth][cull]") {
  // Small versions of the scenes (6 x 6 particles), at times when they fold or twist.
  for (const auto& [name, steps, k, stride] : {std::tuple{"pile", 300, 150, 10}, std::tuple{"twist", 400, 380, 20},
                                               std::tuple{"drape", 300, 280, 10}}) {
    ClothScene s = builtin_cloth_scene(name, 6);
    s.steps = steps;
    const auto frames = simulate_cloth(s);
    const ClothMesh mesh = make_grid_mesh(s);
    const std::vector<Vec3>& x0 = frames[static_cast<std::size_t>(k)];
    const std::vector<Candidate> all = brute_force_candidates(mesh, x0.size());
    for (const bool continuous : {true, false}) {
      const std::vector<Vec3>& x1 = continuous ? frames[static_cast<std::size_t>(k + stride)] : x0;
      // Separation 0.15 (three quarters of the 0.2 m spacing: a flat sheet's non-adjacent
      // primitives are 0.14 m apart, so every fold brings many pairs within it), and
      // separation 0 (true intersections of the unresolved cloth).
      for (const double separation : {0.15, 0.0}) {
        TriangleCcdOptions opt;
        opt.separation = separation;
        std::vector<bool> possible(all.size());
        std::size_t possible_count = 0;
        for (std::size_t i = 0; i < all.size(); ++i) {
          possible[i] = triangle_ccd(all[i].kind, candidate_query(mesh, all[i], x0, x1), opt).status != ccd::QueryStatus::Miss;
          possible_count += possible[i];
        }
        INFO(name << (continuous ? " continuous" : " discrete") << ", separation " << separation << ", possible contacts "
                  << possible_count);
        if (separation > 0) CHECK(possible_count > 0);  // the interval has work for the cullers
        for (const CullerEntry& c : cullers()) {
          INFO(c.name);
          const std::vector<Candidate> got = c.cull(mesh, x0, x1, separation);
          CHECK(std::is_sorted(got.begin(), got.end()));
          CHECK(std::includes(all.begin(), all.end(), got.begin(), got.end()));
          if (c.name != "brute") CHECK(got.size() < all.size());
          for (std::size_t i = 0; i < all.size(); ++i) {
            if (!possible[i] || std::binary_search(got.begin(), got.end(), all[i])) continue;
            INFO("dropped " << to_string(all[i].kind) << " " << all[i].a << " " << all[i].b);
            // Each such pair must be contact-free, decided exactly: at the separation for a
            // conservative culler, at separation 0 for sensors.
            const mpq_class d(separation);
            if (!c.may_drop || separation == 0)
              CHECK_FALSE(exact_contact(all[i].kind, to_rational(candidate_query(mesh, all[i], x0, x1)), d * d));
          }
        }
      }
    }
  }
}

TEST_CASE("normal cones cull the self-tests of a flat sheet entirely", "[cloth][cull]") {
  ClothScene s = builtin_cloth_scene("drape", 8);
  const auto x = initial_positions(s);
  const ClothMesh mesh = make_grid_mesh(s);
  TriangleBvh tree(mesh, x);
  tree.refit(x, x, 0.01);
  BvhStats plain, cones;
  const auto a = tree.self_candidates(false, &plain);
  const auto b = tree.self_candidates(true, &cones);
  CHECK(a.size() > 0);   // neighbouring triangles' boxes touch
  CHECK(b.empty());      // but a flat sheet faces one way: nothing to test
  CHECK(cones.cone_culled == 1);  // at the root
}

TEST_CASE("the box cullers and bvh keep exactly the pairs whose primitive boxes overlap", "[cloth][cull]") {
  // bvh emits each non-adjacent pair whose primitive boxes overlap, whatever its topology;
  // every broad phase reports every overlapping box pair. So all of them agree with
  // boxes:brute exactly, continuous and discrete, with and without a separation.
  ClothScene s = builtin_cloth_scene("pile", 6);
  s.steps = 200;
  const auto frames = simulate_cloth(s);
  const ClothMesh mesh = make_grid_mesh(s);
  for (const bool continuous : {true, false})
    for (const double separation : {0.05, 0.0}) {
      const auto& x0 = frames[150];
      const auto& x1 = continuous ? frames[160] : x0;
      const std::vector<Candidate> reference = find_culler("boxes:brute")->cull(mesh, x0, x1, separation);
      CHECK(!reference.empty());
      for (const CullerEntry& c : cullers()) {
        if (c.name == "brute" || c.may_drop) continue;
        INFO(c.name << (continuous ? " continuous" : " discrete") << ", separation " << separation);
        const std::vector<Candidate> got = c.cull(mesh, x0, x1, separation);
        // Subsets: bvh_cones skips self-tests of patches proved flat, mesh_sweep the pairs
        // whose boxes over both halves of the interval are apart.
        if (c.name == "bvh_cones" || c.name == "mesh_sweep")
          CHECK(std::includes(reference.begin(), reference.end(), got.begin(), got.end()));
        else
          CHECK(got == reference);
      }
    }
}

TEST_CASE("cullers that keep state between intervals give what a fresh instance gives", "[cloth][cull]") {
  // The refitted (and, when its quality degrades, rebuilt) hierarchy and the broad phases
  // kept between frames: over every step interval of a run, the conservative cullers match
  // a fresh instance exactly; the pairs bvh_cones (whose output depends on the topology)
  // and sensors drop are proved contact-free at separation 0.
  ClothScene s = builtin_cloth_scene("pile", 6);
  s.steps = 300;
  const auto frames = simulate_cloth(s);
  const ClothMesh mesh = make_grid_mesh(s);
  const std::vector<Candidate> all = brute_force_candidates(mesh, frames[0].size());
  for (const CullerEntry& c : cullers()) {
    INFO(c.name);
    const auto kept = c.make();
    std::uint64_t rebuilds = 0;
    for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
      const double separation = 0.0;
      const std::vector<Candidate> got = kept->cull(mesh, frames[k], frames[k + 1], separation);
      for (const CullerCounter& counter : kept->counters())
        if (counter.name == "rebuilt") rebuilds += counter.value;
      if (!c.may_drop && c.name != "bvh_cones") {
        CHECK(got == c.cull(mesh, frames[k], frames[k + 1], separation));
        continue;
      }
      if (k % 10 != 0) continue;  // the exact proof on every tenth interval (the pile falls, then folds)
      CHECK(std::includes(all.begin(), all.end(), got.begin(), got.end()));
      for (const Candidate& cand : all) {
        if (std::binary_search(got.begin(), got.end(), cand)) continue;
        const LinearQuery q = candidate_query(mesh, cand, frames[k], frames[k + 1]);
        if (triangle_ccd(cand.kind, q, {}).status == ccd::QueryStatus::Miss) continue;
        INFO("interval " << k << ", dropped " << to_string(cand.kind) << " " << cand.a << " " << cand.b);
        CHECK_FALSE(exact_contact(cand.kind, to_rational(q), 0));
      }
    }
    if (c.name == "bvh" || c.name == "bvh_cones") {
      // Built once, then rebuilt only when refitting loosened the tree: not every step.
      CHECK(rebuilds >= 1);
      CHECK(rebuilds < frames.size() / 4);
    }
  }
}

TEST_CASE("culler names: every broad phase behind boxes:, options, unknown names", "[cloth][cull]") {
  for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry())
    CHECK(find_culler("boxes:" + std::string(info.name)) != nullptr);
  const CullerEntry* grid = find_culler("boxes:grid:cell=0.5");
  REQUIRE(grid != nullptr);
  CHECK(grid->name == "boxes:grid:cell=0.5");
  CHECK(find_culler("boxes:grid:cell=0.5") == grid);  // resolved once
  CHECK_FALSE(grid->may_drop);
  CHECK(find_culler("boxes:nope") == nullptr);
  CHECK(find_culler("boxes:grid:size=1") == nullptr);
  CHECK(find_culler("boxes:") == nullptr);
  CHECK(find_culler("nope") == nullptr);
  CHECK_FALSE(find_culler("bvh_cones")->may_drop);
  CHECK(find_culler("sensors")->may_drop);
}

TEST_CASE("the bvh is rebuilt when refitting degrades it, and only then", "[cloth][cull]") {
  // Built on a flat sheet, then refitted to the same sheet with its particles shuffled
  // (every triangle a long sliver across the sheet): the refitted tree's quality degrades
  // far beyond the rebuild factor, so that call rebuilds; the next call on the same state
  // keeps the new tree. Candidates stay those of boxes:brute throughout.
  ClothScene s = builtin_cloth_scene("drape", 8);
  const ClothMesh mesh = make_grid_mesh(s);
  const std::vector<Vec3> flat = initial_positions(s);
  std::vector<Vec3> shuffled = flat;
  std::mt19937_64 rng(16);
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  auto rebuilt = [](const Culler& c) {
    for (const CullerCounter& counter : c.counters())
      if (counter.name == "rebuilt") return counter.value;
    return std::uint64_t{99};
  };
  for (const char* name : {"bvh", "bvh_cones"}) {
    INFO(name);
    const auto c = find_culler(name)->make();
    c->cull(mesh, flat, flat, 0.01);
    CHECK(rebuilt(*c) == 1);  // the first call builds
    c->cull(mesh, flat, flat, 0.01);
    CHECK(rebuilt(*c) == 0);
    TriangleBvh refitted(mesh, flat);
    refitted.refit(flat, flat, 0.005);
    const double built = refitted.quality();
    refitted.refit(shuffled, shuffled, 0.005);
    CHECK(refitted.quality() > BvhCuller::kRebuildFactor * built);
    const auto got = c->cull(mesh, shuffled, shuffled, 0.01);
    CHECK(rebuilt(*c) == 1);
    if (std::string(name) == "bvh") CHECK(got == find_culler("boxes:brute")->cull(mesh, shuffled, shuffled, 0.01));
    c->cull(mesh, shuffled, shuffled, 0.01);
    CHECK(rebuilt(*c) == 0);
  }
}

}  // namespace cloth_cull_cullers_test
