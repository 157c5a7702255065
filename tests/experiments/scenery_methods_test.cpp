// Every bound (with the grid broad phase, and the continuous ones also with the kinematic
// principle and under the earliest-contact scheduler, with and without speed-adapted
// windows and speed re-checks) against scenery, through the runner and the exact static
// truth: conservative
// methods miss no body-static event, and no method confirms a static contact the truth
// does not have. Scenes: dyadic adversarial cases (grazing a vertex and an edge, tangent
// to a face at the horizon, sliding parallel to a face at distance exactly r, contact
// after and exactly at a wall reflection, after an acceleration change, a fast ball
// through a thin plate), with step boundaries on the contact instants; and balls falling
// through a stack of thin plates. A scene without scenery has every static field 0.
#include "../../experiments/method.hpp"
#include "../../experiments/run_experiment.hpp"
#include "../../experiments/runner.hpp"
#include "../ccd/scene/body_builder.hpp"
#include "../ccd/scene/scenery_support.hpp"

#include <bounds/registry.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/static_truth.hpp>

#include <catch2/catch.hpp>

namespace experiments_scenery_methods_test {

namespace {

using ccd::Body;
using ccd::Vec3;

ccd::Scene adversarial_scene() {
  ccd::Scene s;
  s.horizon = 1.0;
  s.box = ccd::WallBox{Vec3::Zero(), Vec3::Constant(160)};
  auto add = [&](int k, Body b, std::vector<Vec3> polygon) {
    const Vec3 o(16.0 * k + 16.0, 16.0, 16.0);
    b.position += o;
    for (Vec3& v : polygon) v += o;
    s.bodies.push_back(b);
    s.scenery.push_back(ccd::polygon_from_vertices(std::move(polygon)));
  };
  const std::vector<Vec3> sq{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  add(0, ccd::test::body(0.625, {1.375, 1.5, 1}, {0, 0, -2}), sq);   // grazes the vertex (1, 1, 0) at t = 0.5
  add(1, ccd::test::body(0.5, {1.5, -2, 0}, {0, 4, 0}), sq);         // in the plane, grazes the edge x = 1 over [0.5, 0.75]
  add(2, ccd::test::body(0.25, {0.5, 0.5, 2.25}, {0, 0, -2}), sq);   // tangent to the face at the horizon t = 1
  add(3, ccd::test::body(0.25, {-1, 0.5, 0.25}, {2, 0, 0}), sq);     // slides at height r, enters over x = 0 at 0.5
  {
    Body b = ccd::test::body(0.25, {0.5, 0.5, 1}, Vec3::Zero(), {0, 0, -4});  // z = 0.25 at t = 0.875
    b.acceleration_changes.push_back({0.25, Vec3::Zero()});
    add(4, b, sq);
  }
  add(5, ccd::test::body(0.125, {0.5, 0.5, 20}, {0, 0, -40}), sq);   // through the thin plate at t ~ 0.5
  // Wall x = 0: from (1, 2, 2) at (-4, 8, 0) the ball reflects at t = 0.1875 (x = 0.25,
  // y = 3.5), reaches the plate x = 1.5 at t = 0.4375; touches the plate y = 3.75 exactly
  // at the reflection.
  s.bodies.push_back(ccd::test::body(0.25, {1, 2, 2}, {-4, 8, 0}));
  s.scenery.push_back(ccd::polygon_from_vertices({{1.5, 5, 1}, {1.5, 7, 1}, {1.5, 7, 3}, {1.5, 5, 3}}));
  s.bodies.push_back(ccd::test::body(0.25, {1, 2, 6}, {-4, 8, 0}));
  s.scenery.push_back(ccd::polygon_from_vertices({{0, 3.75, 5}, {0, 3.75, 7}, {1, 3.75, 7}, {1, 3.75, 5}}));
  return s;
}

struct Checked {
  std::uint64_t detected = 0, saved = 0;
};

Checked check_methods(const ccd::Scene& scene, double dt, const std::string& what, bool kinematic_exact) {
  const ccd::Trajectories traj(scene);
  const ccdlab::TruthIndex truth(ccd::compute_truth(traj));
  const std::vector<ccd::StaticEvent> events = ccd::compute_static_truth(traj, scene.scenery, 1);
  REQUIRE(!events.empty());
  ccdlab::RunInput in;
  in.scene = &scene;
  const ccd::RigidMotion scene_motion(scene, traj);
  in.motion = &scene_motion;
  in.truth = &truth;
  in.static_events = events;
  in.acceleration_bound = scene.max_acceleration();
  Checked out;
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    std::vector<std::string> names{std::string(b.name) + "/grid"};
    if (b.knowledge != ccd::Knowledge::Instant) {
      names.push_back(std::string(b.name) + "/grid@fixed:kinematic=1");
      names.push_back(std::string(b.name) + "/grid@earliest");
      names.push_back(std::string(b.name) + "/grid@earliest:reach=2,recheck=1");
    }
    for (const std::string& name : names) {
      INFO(what << " " << name << " dt " << dt);
      const ccdlab::RunRecord r = ccdlab::run_method(in, ccdlab::parse_method(name), dt);
      CHECK(r.scenery.events == events.size());
      CHECK(r.scenery.initial_contacts + r.scenery.detected + r.scenery.missed == r.scenery.events);
      CHECK(r.self_check_unexpected == 0);
      if (r.scheduled) {
        CHECK(r.scenery.passed <= r.scenery.checks);
        CHECK(r.scenery.confirmed <= r.scenery.narrow_calls);
        CHECK(ccdlab::to_json(r)["static_narrow_calls"] == r.scenery.narrow_calls);
      }
      const bool kinematic = name.find("kinematic=1") != std::string::npos;
      if (r.continuous && r.conservative && (!kinematic || kinematic_exact)) CHECK(r.scenery.missed == 0);
      if (!kinematic) CHECK(r.scenery.tests_saved == 0);
      out.detected += r.scenery.detected;
      out.saved += r.scenery.tests_saved;
    }
  }
  return out;
}

}  // namespace

TEST_CASE("conservative methods miss no body-static event on the dyadic cases", "[runner][methods][scenery]") {
  const ccd::Scene scene = adversarial_scene();
  // dt = 1/8 and 1/16 put step boundaries on the contact instants (0.1875, 0.25, 0.4375,
  // 0.5, 0.875, 1); 1/2 makes every contact fall inside a long step.
  for (const double dt : {0.125, 0.0625, 0.5}) {
    const Checked c = check_methods(scene, dt, "adversarial", true);  // one polygon per body
    CHECK(c.detected > 0);
  }
}

TEST_CASE("conservative methods miss no body-static event among thin plates", "[runner][methods][scenery]") {
#ifdef CCDLAB_SANITIZED
  const int bodies = 12;
#else
  const int bodies = 24;
#endif
  const ccd::Scene scene = ccd::test::plates_scene(1407, bodies);
  const Checked c = check_methods(scene, 0.0625, "plates", false);
  CHECK(c.detected > 0);
  CHECK(c.saved > 0);  // several plates per body and step: the kinematic principle skips some
}

TEST_CASE("a scene without scenery has every static field 0", "[runner][scenery]") {
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.5, {0, 0, 0}, {1, 0, 0}));
  s.bodies.push_back(ccd::test::body(0.5, {3, 0, 0}, {-1, 0, 0}));
  const ccd::Trajectories traj(s);
  const ccdlab::TruthIndex truth(ccd::compute_truth(traj));
  ccdlab::RunInput in;
  in.scene = &s;
  const ccd::RigidMotion scene_motion(s, traj);
  in.motion = &scene_motion;
  in.truth = &truth;
  const ccdlab::RunRecord r = ccdlab::run_method(in, ccdlab::parse_method("capsule/grid@fixed:kinematic=1"), 0.25);
  CHECK(r.bodies.detected == 1);
  CHECK(r.scenery.events == 0);
  CHECK(r.scenery.detected == 0);
  CHECK(r.scenery.missed == 0);
  CHECK(r.scenery.candidates == 0);
  CHECK(r.scenery.tests_saved == 0);
  const nlohmann::json j = ccdlab::to_json(r);
  CHECK(j["static_events"] == 0);
  CHECK(j["static_missed"] == 0);
}

TEST_CASE("@earliest runs on a scene with scenery and refuses the kinematic option", "[runner][scenery]") {
  ccdlab::Experiment e;
  e.scene_generator = {{"generator", "floor_ramp"}, {"bodies", 4}};
  e.methods = {ccdlab::parse_method("capsule/grid"), ccdlab::parse_method("capsule/grid@earliest")};
  CHECK_FALSE(ccdlab::load_experiment_scene(e, "e.json").scenery.empty());
  try {
    ccdlab::parse_method("capsule/grid@earliest:kinematic=1");
    FAIL("@earliest:kinematic=1 was accepted");
  } catch (const std::invalid_argument& err) {
    CHECK(std::string(err.what()).find("kinematic") != std::string::npos);
  }
}

}  // namespace experiments_scenery_methods_test
