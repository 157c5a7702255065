// Every bound with every broad phase, through the runner, on small scenes with walls,
// gravity and different accelerations: conservative methods miss nothing, discrete
// methods detect exactly the events that contain a sample time, and every method's
// self-check passes. Iterates the registries, so a new bound or broad phase is covered;
// every space-time method also runs under the earliest scheduler (BOUND/BROADPHASE@earliest),
// with windows of dt, with speed-adapted ones (`reach`) and with speed re-checks (`recheck`).
#include "../../experiments/method.hpp"
#include "../../experiments/runner.hpp"
#include "method_cover.hpp"

#include <generators/registry.hpp>

#include <catch2/catch.hpp>

namespace experiments_all_methods_test {

namespace {

struct Case {
  const char* generator;
  nlohmann::json params;
  double dt;
};

}  // namespace

TEST_CASE("every method composes and keeps its guarantee on small scenes", "[runner][methods]") {
  const Case c = GENERATE(Case{"gas", {{"bodies", 120}, {"seed", 11}, {"speed_max", 30}, {"horizon", 0.5}}, 0.05},
                          Case{"rain", {{"bodies", 120}, {"seed", 12}, {"horizon", 1.0}, {"aspect", 1}}, 0.05},
                          Case{"swarm", {{"bodies", 100}, {"seed", 13}, {"horizon", 0.5}, {"fraction", 0.1}}, 0.1},
                          Case{"bullets", {{"bodies", 80}, {"seed", 14}, {"bullets", 8}, {"horizon", 0.5}}, 0.02},
                          Case{"lattice", {{"bodies", 64}, {"seed", 15}, {"speed", 0.5}, {"horizon", 0.5}}, 0.1});
  const ccd::Scene scene = ccdlab::generate_scene(c.generator, c.params);
  const ccd::Trajectories traj(scene);
  const ccdlab::TruthIndex truth(ccd::compute_truth(traj));
  ccdlab::RunInput in;
  in.scene = &scene;
  const ccd::RigidMotion scene_motion(scene, traj);
  in.motion = &scene_motion;
  in.truth = &truth;
  in.acceleration_bound = scene.max_acceleration();
  REQUIRE(!truth.events().empty());
  std::vector<std::string> names = ccdlab::all_method_names();
  for (const std::string& m : ccdlab::scheduled_method_names()) {
    names.push_back(m);
    names.push_back(m + ":reach=1");  // speed-adapted windows: the broad phases' incremental updates
    names.push_back(m + ":recheck=1");  // speed re-checks and chunked narrow calls
  }
  for (const std::string& name : ccdlab::test::sanitizer_cover(names)) {
    INFO(c.generator << " " << name);
    const ccdlab::RunRecord r = ccdlab::run_method(in, ccdlab::parse_method(name), c.dt);
    CHECK(r.bodies.events == truth.events().size());
    CHECK(r.bodies.initial_contacts + r.bodies.detected + r.bodies.missed == r.bodies.events);
    CHECK(r.self_check_unexpected == 0);
    CHECK(r.self_check_undetected == 0);
    CHECK(r.counts_stable);
    if (r.continuous && r.conservative) CHECK(r.bodies.missed == 0);
    // The bullets tunnel through the field at this dt: sampling must miss some of them,
    // or the scene does not test what it is meant to.
    if (!r.continuous && std::string(c.generator) == "bullets") CHECK(r.bodies.missed > 0);
  }
}

}  // namespace experiments_all_methods_test
