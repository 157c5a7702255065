// Every fixed-step method (every bound with every broad phase) on scenes that wrap
// around, through the runner: conservative methods miss nothing, discrete methods detect
// exactly the events that contain a sample time (the runner's self-check), on a gas that
// crosses the seam often and on the dyadic seam cases (contact at the crossing instant, at
// t = 0 and at the horizon, a body on the face, tangent across the seam and a corner).
// Every `@earliest` method too, with its options (speed-adapted windows, body refreshes,
// speed re-checks and their chunks).
#include "../../experiments/method.hpp"
#include "../../experiments/run_experiment.hpp"
#include "../../experiments/runner.hpp"
#include "../ccd/scene/periodic_scenes.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <generators/registry.hpp>

#include <catch2/catch.hpp>

namespace experiments_wrapped_methods_test {

namespace {

void check_methods(const ccd::Scene& scene, double dt, const std::string& what, const std::vector<std::string>& names) {
  const ccd::Trajectories traj(scene);
  const ccdlab::TruthIndex truth(ccd::compute_truth(traj));
  ccdlab::RunInput in;
  in.scene = &scene;
  const ccd::RigidMotion scene_motion(scene, traj);
  in.motion = &scene_motion;
  in.truth = &truth;
  in.acceleration_bound = scene.max_acceleration();
  REQUIRE(!truth.events().empty());
  for (const std::string& name : names) {
    INFO(what << " " << name);
    const ccdlab::RunRecord r = ccdlab::run_method(in, ccdlab::parse_method(name), dt);
    CHECK(r.bodies.events == truth.events().size());
    CHECK(r.bodies.initial_contacts + r.bodies.detected + r.bodies.missed == r.bodies.events);
    CHECK(r.self_check_unexpected == 0);
    CHECK(r.self_check_undetected == 0);
    if (r.continuous && r.conservative) CHECK(r.bodies.missed == 0);
    CHECK(r.counts_stable);
  }
}

void check_every_method(const ccd::Scene& scene, double dt, const std::string& what) {
  check_methods(scene, dt, what, ccdlab::all_method_names());
}

// Every scheduled method with its default options and with each option that changes how
// it covers time.
std::vector<std::string> scheduled_variants() {
  std::vector<std::string> names;
  for (const std::string& m : ccdlab::scheduled_method_names()) {
    names.push_back(m);
    names.push_back(m + ":stale=0.01,refresh_bodies=1,align=0");
    names.push_back(m + ":recheck=1,chunk=0");
#ifndef CCDLAB_SANITIZED  // the scheduler test covers these under the sanitizers
    names.push_back(m + ":reach=1");
    names.push_back(m + ":recheck=1");
#endif
  }
  return names;
}

}  // namespace

TEST_CASE("every method keeps its guarantee on a gas that wraps around", "[runner][methods][periodic]") {
#ifdef CCDLAB_SANITIZED
  const int bodies = 40;
#else
  const int bodies = 100;
#endif
  const ccd::Scene scene = ccdlab::generate_scene(
      "gas", {{"bodies", bodies}, {"seed", 21}, {"speed_max", 30}, {"horizon", 0.5}, {"wrap", 1}});
  REQUIRE(scene.wraps());
  check_every_method(scene, 0.05, "gas wrap=1");
}

TEST_CASE("every method keeps its guarantee on the dyadic seam cases", "[runner][methods][periodic]") {
  for (const ccd::test::PeriodicCase& c : ccd::test::periodic_cases()) {
    // dt = 0.25 puts step boundaries (and sample times) on the contact instants 0.5, 1, 2, 3.
    check_every_method(c.scene, 0.25, c.name);
  }
  // A random dyadic scene with gravity along a wrapped axis and acceleration changes.
  check_every_method(ccd::test::random_periodic_scene(5, 40), 0.125, "random periodic");
}

TEST_CASE("every @earliest method keeps its guarantee on scenes that wrap around", "[runner][methods][periodic]") {
#ifdef CCDLAB_SANITIZED
  const int bodies = 40;
#else
  const int bodies = 80;
#endif
  const std::vector<std::string> names = scheduled_variants();
  const ccd::Scene gas = ccdlab::generate_scene(
      "gas", {{"bodies", bodies}, {"seed", 21}, {"speed_max", 30}, {"horizon", 0.5}, {"wrap", 1}});
  check_methods(gas, 0.05, "gas wrap=1", names);
  for (const ccd::test::PeriodicCase& c : ccd::test::periodic_cases()) check_methods(c.scene, 0.25, c.name, names);
  check_methods(ccd::test::random_periodic_scene(5, 40), 0.125, "random periodic", names);
}

TEST_CASE("an @earliest experiment on a scene that wraps around loads", "[runner][periodic]") {
  ccdlab::Experiment e;
  e.scene_generator = {{"generator", "gas"}, {"bodies", 10}, {"wrap", 1}};
  e.methods = {ccdlab::parse_method("capsule/sap"), ccdlab::parse_method("capsule/sap@earliest")};
  const ccd::Scene scene = ccdlab::load_experiment_scene(e, "e.json");
  CHECK(scene.wraps());
}

}  // namespace experiments_wrapped_methods_test
