// Ground truth of scenes that wrap around: against worked-out dyadic cases, and against
// the same scene tiled 3 x 3 x 3 without walls (the central copy's events), event for event.
#include "../scene/periodic_scenes.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/contact_function.hpp>
#include <ccd/truth/ground_truth.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace ccd_truth_periodic_truth_test {

namespace {

using ccd::ContactEvent;

// The periodic truth and the tiled one solve the same motion from different expansion
// points (pieces end at the seam in one, not in the other), so their times agree to the
// solver's rounding: a few ulps of the horizon, far below 1e-12 s on these dyadic scenes.
constexpr double kTimeTol = 1e-12;

void require_same(const std::vector<ContactEvent>& x, const std::vector<ContactEvent>& y) {
  REQUIRE(x.size() == y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    INFO("event " << i << ": (" << x[i].a << ", " << x[i].b << ") [" << x[i].enter << ", " << x[i].exit << "] vs ("
                  << y[i].a << ", " << y[i].b << ") [" << y[i].enter << ", " << y[i].exit << "]");
    CHECK(x[i].a == y[i].a);
    CHECK(x[i].b == y[i].b);
    CHECK(std::fabs(x[i].enter - y[i].enter) <= kTimeTol);
    CHECK(std::fabs(x[i].exit - y[i].exit) <= kTimeTol);
  }
}

}  // namespace

TEST_CASE("periodic truth: dyadic cases across the seam", "[truth][periodic]") {
  for (const ccd::test::PeriodicCase& c : ccd::test::periodic_cases()) {
    SECTION(c.name) {
      REQUIRE_NOTHROW(ccd::validate_scene(c.scene, "case.json"));
      const ccd::Trajectories traj(c.scene);
      const auto events = ccd::compute_truth(traj);
      require_same(events, c.expected);
      require_same(ccd::compute_truth_all_pairs(traj), c.expected);
      // The tiled scene agrees (central copy).
      const ccd::test::Tiling t = ccd::test::tiled(c.scene);
      require_same(ccd::test::central_events(ccd::compute_truth(ccd::Trajectories(t.scene)), c.scene.bodies.size(),
                                             t.central),
                   c.expected);
    }
  }
}

TEST_CASE("periodic truth: positions stay in the box on wrapped axes", "[truth][periodic]") {
  const ccd::Scene s = ccd::test::random_periodic_scene(7, 40);
  const ccd::Trajectories traj(s);
  std::size_t wraps = 0;
  for (std::size_t i = 0; i < traj.size(); ++i) {
    const auto ps = traj.pieces(i);
    for (std::size_t j = 0; j < ps.size(); ++j) {
      for (double t : {ps[j].t0, 0.5 * (ps[j].t0 + ps[j].t1), ps[j].t1}) {
        const ccd::Vec3 p = ps[j].position(t);
        for (int k = 0; k < 3; ++k) {
          // Within rounding of the piece's end time (|v| <= 4, times of 2 s).
          CHECK(p[k] >= -1e-12);
          CHECK(p[k] <= 16.0 + 1e-12);
        }
      }
      if (j > 0 && (ps[j - 1].position(ps[j].t0) - ps[j].p).cwiseAbs().maxCoeff() > 8.0) ++wraps;
    }
  }
  // The scene is meant to cross the seam often: a test that never wraps tests nothing.
  CHECK(wraps > 10);
}

TEST_CASE("periodic truth equals the central copy of the 3 x 3 x 3 tiling, event for event",
          "[truth][periodic]") {
  const std::uint64_t seed = GENERATE(1, 2, 3);
  const ccd::Scene s = ccd::test::random_periodic_scene(seed, 60);
  REQUIRE_NOTHROW(ccd::validate_scene(s, "random.json"));
  const ccd::Trajectories traj(s);
  const auto events = ccd::compute_truth(traj);
  const ccd::test::Tiling t = ccd::test::tiled(s);
  const auto reference = ccd::test::central_events(ccd::compute_truth(ccd::Trajectories(t.scene)), s.bodies.size(),
                                                   t.central);
  INFO("seed " << seed << ": " << events.size() << " events");
  CHECK(events.size() > 10);
  require_same(events, reference);
  // The truth's broad phase (with images) loses nothing against all pairs.
  require_same(events, ccd::compute_truth_all_pairs(traj));
}

TEST_CASE("periodic contact test uses the nearest image", "[truth][periodic]") {
  const ccd::test::PeriodicCase c = ccd::test::periodic_cases()[2];  // a body on the face, the other through the seam
  const ccd::Trajectories traj(c.scene);
  CHECK_FALSE(ccd::in_contact(traj, 0, 1, 0.5));
  CHECK(ccd::in_contact(traj, 0, 1, 1.0));   // x = 7 and 0 (image 8): distance 1, touching
  CHECK(ccd::in_contact(traj, 0, 1, 2.0));   // on the seam
  CHECK(ccd::in_contact(traj, 0, 1, 2.5));   // through it
  CHECK_FALSE(ccd::in_contact(traj, 0, 1, 3.5));
}

}  // namespace ccd_truth_periodic_truth_test
