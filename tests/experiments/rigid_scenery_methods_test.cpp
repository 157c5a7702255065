// Every bound (grid broad phase; the continuous ones also with the kinematic principle and
// under the earliest-contact scheduler) on rigid bodies against scenery, through the runner and the certified rigid static
// truth: conservative methods miss no body-static event and no method confirms a static
// contact the truth does not have. Scenes: the hand-worked cases of
// rigid_scenery_scenes.hpp (face on face, a spinning tip across an edge, corner on vertex,
// t = 0, the horizon, far from the origin) with step boundaries on the contact instants,
// a body resting exactly on a polygon, and the `tumble` generator's random scene.
#include "../../experiments/method.hpp"
#include "../../experiments/runner.hpp"
#include "../ccd/scene/rigid_scenery_scenes.hpp"

#include <bounds/registry.hpp>
#include <ccd/truth/rigid_static_truth.hpp>
#include <ccd/truth/rigid_truth.hpp>
#include <generators/registry.hpp>

#include <algorithm>
#include <catch2/catch.hpp>

namespace experiments_rigid_scenery_methods_test {

namespace {

struct Checked {
  std::uint64_t detected = 0, saved = 0, sampled_missed = 0;
};

Checked check_methods(const ccd::Scene& scene, double dt, const std::string& what, bool kinematic_exact,
                      const ccd::RigidTruthOptions& options = {}) {
  const ccd::Trajectories traj(scene);
  const ccd::RigidMotion motion(scene, traj);
  const ccd::RigidTruthResult body_truth = ccd::compute_rigid_truth(motion, options);
  const ccd::RigidStaticTruthResult st = ccd::compute_rigid_static_truth(motion, scene.scenery, options);
  REQUIRE(!st.events.empty());
  const double err = std::max(ccd::largest_error(body_truth.errors), ccd::largest_error(st.errors));
  const ccdlab::TruthIndex truth(body_truth.events);
  ccdlab::RunInput in;
  in.scene = &scene;
  in.motion = &motion;
  in.truth = &truth;
  in.truth_error = err;
  in.static_events = st.events;
  in.acceleration_bound = scene.max_acceleration();
  Checked out;
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    std::vector<std::string> names{std::string(b.name) + "/grid"};
    if (b.knowledge != ccd::Knowledge::Instant) {
      names.push_back(std::string(b.name) + "/grid@fixed:kinematic=1");
      names.push_back(std::string(b.name) + "/grid@earliest");
    }
    for (const std::string& name : names) {
      INFO(what << " " << name << " dt " << dt);
      const ccdlab::RunRecord r = ccdlab::run_method(in, ccdlab::parse_method(name), dt);
      CHECK(r.scenery.events == st.events.size());
      CHECK(r.scenery.initial_contacts + r.scenery.detected + r.scenery.missed == r.scenery.events);
      CHECK(r.self_check_unexpected == 0);
      const bool kinematic = name.find("kinematic=1") != std::string::npos;
      if (r.continuous && r.conservative && (!kinematic || kinematic_exact)) CHECK(r.scenery.missed == 0);
      if (!r.continuous) out.sampled_missed += r.scenery.missed;
      out.detected += r.scenery.detected;
      out.saved += r.scenery.tests_saved;
    }
  }
  return out;
}

}  // namespace

TEST_CASE("conservative methods miss no rigid body-static event on the hand-worked cases",
          "[runner][methods][scenery][rigid]") {
  const ccd::Scene scene = ccd::test::rigid_static_cases();
  // dt = 1/4 and 1/2 put step boundaries on the contact instants 1/2, 1, 3/2 and 2; 1/3
  // does not.
  for (const double dt : {0.25, 0.5, 1.0 / 3.0}) {
    const Checked c = check_methods(scene, dt, "cases", true);  // one polygon per body
    CHECK(c.detected > 0);
  }
}

TEST_CASE("conservative methods detect a body resting exactly on a polygon", "[runner][methods][scenery][rigid]") {
  ccd::RigidTruthOptions o;
  o.max_evaluations = 4096;  // touching throughout: nothing to certify (grazing)
  const Checked c = check_methods(ccd::test::resting_scene(), 0.25, "resting", true, o);
  CHECK(c.detected > 0);
}

TEST_CASE("conservative methods miss no rigid body-static event in the tumble scene", "[runner][methods][scenery][rigid]") {
#ifdef CCDLAB_SANITIZED
  const int bodies = 6;
#else
  const int bodies = 12;
#endif
  const ccd::Scene scene = ccdlab::generate_scene(
      "tumble", nlohmann::json{{"bodies", bodies}, {"horizon", 2.0}, {"seed", 5}, {"spin_max", 16.0}});
  REQUIRE(scene.has_non_spheres());
  const Checked c = check_methods(scene, 0.0625, "tumble", false);
  CHECK(c.detected > 0);
}

}  // namespace experiments_rigid_scenery_methods_test
