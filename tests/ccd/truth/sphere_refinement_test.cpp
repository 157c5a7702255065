// The second look at a ball's grazing events (ccd/truth/sphere_refinement.hpp): a plate
// spinning 5e-7 from two resting balls has no event (the bracket search alone ran out of
// evaluations and reported 26 grazing ones), a gap below what the distance can certify is
// undecided (not a contact), and touching or crossing pairs are still found.
#include <ccd/truth/truth.hpp>

#include "../scene/plate_scenes.hpp"

#include <catch2/catch.hpp>
#include <cmath>

namespace ccd_truth_sphere_refinement_test {

using ccd::Vec3;

namespace {

ccd::Truth truth_of(const ccd::Scene& scene, std::size_t max_evaluations = 0) {
  const ccd::Trajectories traj(scene);
  const ccd::RigidMotion motion(scene, traj);
  ccd::TruthOptions o;
  o.threads = 1;
  if (max_evaluations) o.max_evaluations = max_evaluations;
  return ccd::compute_truth(motion, {}, o);
}

}  // namespace

TEST_CASE("sphere refinement: a plate spinning 5e-7 from two resting balls has no event", "[truth][rigid][undecided]") {
  // Half extents (1/2, 1/2, 1/100), 10 rad/s; balls of radius 1/10 at z = +-0.1100005: the
  // faces stay at +-0.01, the balls' surfaces at +-(0.01 + 5e-7).
  const ccd::Scene s = ccd::test::spinning_plate_scene(Vec3(0.5, 0.5, 0.01), 10.0, 0.1, {0.1100005, -0.1100005});
  const ccd::Truth t = truth_of(s);  // the default budget, as `ccdlab truth`
  CHECK(t.events.empty());
  CHECK(t.stats.undecided == 0);
  CHECK(t.stats.grazing == 0);
  CHECK(t.stats.candidate_runs == 2);  // both pairs were searched
}

TEST_CASE("sphere refinement: gaps down to about 1e-14 of the extent are certified", "[truth][rigid][undecided]") {
  for (const int k : {20, 30, 40, 44}) {
    CAPTURE(k);
    const ccd::Truth t = truth_of(ccd::test::dyadic_plate_scene(10.0, std::ldexp(1.0, -k)), 4096);
    CHECK(t.events.empty());
  }
}

TEST_CASE("sphere refinement: a gap the truth cannot certify is undecided, not a contact",
          "[truth][rigid][undecided]") {
  // 2^-50 (about 9e-16 of the plate's extent): below the distance's rounding allowance.
  const ccd::Truth t = truth_of(ccd::test::dyadic_plate_scene(10.0, std::ldexp(1.0, -50)), 4096);
  REQUIRE(t.events.size() == 2);
  REQUIRE(t.errors.size() == 2);
  CHECK(t.stats.undecided == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(t.events[k].a == 0);
    CHECK(t.events[k].b == k + 1);
    CHECK(t.errors[k].undecided);
    CHECK(t.errors[k].grazing);
    // The bracket: the whole horizon, where nothing was certified.
    CHECK(t.events[k].enter - t.errors[k].enter_error <= 0.0);
    CHECK(t.events[k].exit + t.errors[k].exit_error >= 1.0);
  }
}

TEST_CASE("sphere refinement: touching and crossing pairs are still found", "[truth][rigid][undecided]") {
  SECTION("a plate at rest touching two balls exactly (gap 0): contact over the whole horizon, certified") {
    const ccd::Truth t = truth_of(ccd::test::dyadic_plate_scene(0.0, 0.0), 4096);
    REQUIRE(t.events.size() == 2);
    CHECK(t.stats.undecided == 0);
    for (const ccd::ContactEvent& e : t.events) {
      CHECK(e.enter == 0.0);
      CHECK(e.exit == 1.0);
    }
    CHECK(t.errors.empty());  // both times exact
  }
  SECTION("a plate at rest 2^-40 from the balls: no event") {
    CHECK(truth_of(ccd::test::dyadic_plate_scene(0.0, std::ldexp(1.0, -40)), 4096).events.empty());
  }
  SECTION("a spinning plate touching exactly: reported, undecided (a touch under a turning box is not exact)") {
    const ccd::Truth t = truth_of(ccd::test::dyadic_plate_scene(10.0, 0.0), 4096);
    REQUIRE(t.events.size() == 2);
    for (const ccd::EventError& e : t.errors) CHECK(e.undecided);
  }
  SECTION("a ball falling through the spinning plate: a certified contact, brackets holding 23/64 and 41/64") {
    // The ball (radius 1/8) starts at z = 1/2 moving at -1: it touches the top face z = 1/64
    // at 1/2 - 9/64 = 23/64 and leaves the bottom face at 1/2 + 9/64 = 41/64.
    const ccd::Scene s =
        ccd::test::spinning_plate_scene(Vec3(0.5, 0.5, 0.015625), 10.0, 0.125, {0.5}, Vec3(0, 0, -1));
    const ccd::Truth t = truth_of(s);
    REQUIRE(t.events.size() == 1);
    REQUIRE(t.errors.size() == 1);
    CHECK_FALSE(t.errors[0].undecided);
    CHECK_FALSE(t.errors[0].grazing);
    CHECK(std::fabs(t.events[0].enter - 23.0 / 64) <= t.errors[0].enter_error);
    CHECK(std::fabs(t.events[0].exit - 41.0 / 64) <= t.errors[0].exit_error);
    CHECK(t.errors[0].enter_error < 1e-7);
    CHECK(t.errors[0].exit_error < 1e-7);
  }
}

}  // namespace ccd_truth_sphere_refinement_test
