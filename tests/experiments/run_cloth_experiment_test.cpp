// Cloth jobs against the exact mesh truth on a hand-built dyadic motion whose contacts are
// known: every culler of the registry in both modes; the conservative ones (continuous,
// never dropping a pair) miss nothing at any check interval, and discrete checking misses
// what happens between checks.
#include "../../experiments/run_cloth_experiment.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

namespace experiments_run_cloth_experiment_test {

using namespace ccdlab;
using ccd::Vec3;

namespace {

// Two triangles: A = (0,0,0), (1,0,0), (0,1,0) still; B in the plane y = 1/4 with
// p = (1/4, 1/4, z), q = p + (0, 0, 8), r = (33/4, 1/4, z). At z = 0, p is in A's interior
// and B's edge pr crosses A's hypotenuse: the pairs (p, A) and (pr, hypotenuse) touch.
// z over the states: 1, 1/2, -1/2, -1, -1/2, 1/2, 1, 0, 1: through A in step 1 and in
// step 4 (between states), touching exactly at state 7 (steps 6 and 7). Far from the
// origin, so that rounding is exercised.
ClothMotion hand_built() {
  ClothMotion m;
  m.mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.mesh.edges = {{0, 1}, {0, 2}, {1, 2}, {3, 4}, {3, 5}, {4, 5}};
  const Vec3 o(0x1p10, 0x1p10, -0x1p10);
  for (double z : {1.0, 0.5, -0.5, -1.0, -0.5, 0.5, 1.0, 0.0, 1.0})
    m.frames.push_back({Vec3(0, 0, 0) + o, Vec3(1, 0, 0) + o, Vec3(0, 1, 0) + o, Vec3(0.25, 0.25, z) + o,
                        Vec3(0.25, 0.25, z + 8) + o, Vec3(8.25, 0.25, z) + o});
  m.scene.step = 0.005;
  m.scene.steps = static_cast<int>(m.frames.size()) - 1;
  m.truth = ccd::cloth::compute_mesh_truth(m.mesh, m.frames, 0.0);
  m.events = ccd::cloth::contact_events(m.truth);
  return m;
}

}  // namespace

TEST_CASE("cloth jobs: conservative cullers miss nothing, discrete checks miss what passes between them",
          "[cloth][experiments]") {
  const ClothMotion m = hand_built();
  REQUIRE(m.events.size() == 6);  // two pairs x (step 1, step 4, steps 6-7)
  for (const auto& culler : ccd::cloth::cullers())
    for (int k : {1, 2, 3, 4, 8}) {
      CAPTURE(culler.name, k);
      const ClothRecord c = run_cloth_method(m, culler, true, k);
      CHECK(c.method == std::string(culler.name) + "/continuous");
      CHECK(c.detected + c.missed == 6);
      CHECK(c.checks == (8u + k - 1) / k);
      CHECK(c.narrow_calls == c.candidates);
      CHECK(c.confirmed <= c.candidates);
      CHECK(c.dt == k * 0.005);
      if (!culler.may_drop) {
        CHECK(c.conservative);
        CHECK(c.missed == 0);
      }
      if (k == 1) CHECK(c.max_separation == 0.0);  // no intermediate state: nothing widened
      if (k == 2) CHECK(c.max_separation >= 2.0);  // state 7 (z = 0) is 1 below the chord from state 6 to 8 (z = 1)
      const ClothRecord d = run_cloth_method(m, culler, false, k);
      CHECK(d.checks == 8u / k + 1);
      CHECK_FALSE(d.conservative);
      CHECK(d.detected + d.missed == 6);
      if (!culler.may_drop) {
        // Only state 7 has contacts: checked at k = 1 (the two events of steps 6-7), never
        // at k = 2, 3, 4, 8 (7 is not a multiple).
        CHECK(d.detected == (k == 1 ? 2u : 0u));
        CHECK(d.false_positives == 0);
      }
    }
}

TEST_CASE("cloth jobs: false positives and repeats", "[cloth][experiments]") {
  const ClothMotion m = hand_built();
  const auto& brute = *ccd::cloth::find_culler("brute");
  // Continuous at k = 8: one interval over everything; its chord (z 1 -> 1) never moves
  // but is widened by twice the largest departure (2, at z = -1): every pair near the
  // triangles is confirmed, and those not in contact are false positives.
  const ClothRecord wide = run_cloth_method(m, brute, true, 8);
  CHECK(wide.missed == 0);
  CHECK(wide.max_separation >= 4.0);
  CHECK(wide.false_positives == wide.confirmed - 2);  // all but the two true pairs
  CHECK(wide.false_positives > 0);
  // k = 1: the truth's own question; the kernel finds exactly the four step contacts of
  // steps 1 and 4 and the four of steps 6 and 7, nothing else (exact dyadic geometry).
  const ClothRecord exact = run_cloth_method(m, brute, true, 1);
  CHECK(exact.confirmed == 8);
  CHECK(exact.false_positives == 0);
  const ClothRecord thrice = run_cloth_method(m, brute, true, 2, 3);
  CHECK(thrice.counts_stable);
  CHECK(thrice.candidates == run_cloth_method(m, brute, true, 2).candidates);
}

}  // namespace experiments_run_cloth_experiment_test
