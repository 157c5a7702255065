// Small versions of the stability studies (docs/studies.md, data/experiments/<study>*.json),
// run through the runner library on small generated scenes, asserting each study's key
// outcome. Counts only: speed is never asserted.
#include "../../generators/registry.hpp"
#include "../../experiments/runner.hpp"

#include <ccd/geometry/aabb.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/rigid_truth.hpp>
#include <ccd/truth/static_truth.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace experiments_studies_test {

using nlohmann::json;

namespace {

struct Study {
  ccd::Scene scene;
  ccd::Trajectories traj;
  ccdlab::TruthIndex truth;
  Study(const std::string& generator, const json& params)
      : scene(ccdlab::generate_scene(generator, params)), traj(scene), truth(ccd::compute_truth(traj)) {}
  ccdlab::RunRecord run(const std::string& method, double dt, double A = -1.0) const {
    ccdlab::RunInput in;
    in.scene = &scene;
    const ccd::RigidMotion scene_motion(scene, traj);
    in.motion = &scene_motion;
    in.truth = &truth;
    in.acceleration_bound = A >= 0.0 ? A : scene.max_acceleration();
    return ccdlab::run_method(in, ccdlab::parse_method(method), dt);
  }
};

// A rigid study: the generated scene's shapes and spin, and its certified rigid truth.
struct RigidStudy {
  ccd::Scene scene;
  ccd::Trajectories traj;
  ccd::RigidMotion motion;
  ccd::RigidTruthResult rt;
  ccdlab::TruthIndex truth;
  double error = 0.0;
  RigidStudy(const std::string& generator, const json& params)
      : scene(ccdlab::generate_scene(generator, params)), traj(scene), motion(scene, traj),
        rt(ccd::compute_rigid_truth(motion)), truth(rt.events) {
    error = ccd::largest_error(rt.errors);
  }
  ccdlab::RunRecord run(const std::string& method, double dt) const {
    ccdlab::RunInput in;
    in.scene = &scene;
    in.motion = &motion;
    in.truth = &truth;
    in.truth_error = error;
    in.acceleration_bound = scene.max_acceleration();
    return ccdlab::run_method(in, ccdlab::parse_method(method), dt);
  }
};

const std::vector<std::string> kConservative = {"swept_aabb/sap", "capsule/sap", "horn:4/sap", "horn_sat:4/sap",
                                                "enclosing_sphere/grid"};

// Every record must pass the runner's self-check (no contact the truth lacks; discrete:
// every event with a sample well inside it detected).
void check_self(const ccdlab::RunRecord& r) {
  CHECK(r.self_check_unexpected == 0);
  CHECK(r.self_check_undetected == 0);
}

// Pairs whose boxes overlap on all three axes, with closed (<=) or strict (<) comparisons.
std::size_t count_box_pairs(const std::vector<ccd::Aabb>& boxes, bool strict) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      bool all = true;
      for (int a = 0; a < 3 && all; ++a) {
        const double lo_i = boxes[i].lo[a], hi_i = boxes[i].hi[a], lo_j = boxes[j].lo[a], hi_j = boxes[j].hi[a];
        all = strict ? (lo_j < hi_i && lo_i < hi_j) : (lo_j <= hi_i && lo_i <= hi_j);
      }
      n += all;
    }
  return n;
}

// A record's summed counter `name`, 0 when the broad phase has no such counter.
std::uint64_t counter(const ccdlab::RunRecord& r, const std::string& name) {
  for (const auto& [n, v] : r.counters)
    if (n == name) return v;
  return 0;
}

}  // namespace

TEST_CASE("study tunnelling: conservative bounds miss nothing, discrete methods tunnel at a coarse dt",
          "[studies]") {
  const Study s("bullets", {{"bodies", 200}, {"bullets", 20}, {"seed", 1}});
  REQUIRE(s.truth.events().size() > 10);
  for (const std::string& m : kConservative)
    for (double dt : {0.1, 0.01}) {
      CAPTURE(m, dt);
      const auto r = s.run(m, dt);
      CHECK(r.bodies.missed == 0);
      CHECK(r.bodies.detected + r.bodies.initial_contacts == r.bodies.events);
      check_self(r);
    }
  const auto coarse = s.run("aabb/sap", 0.1);
  const auto fine = s.run("aabb/sap", 0.001);
  CHECK(coarse.bodies.missed > 0);
  CHECK(fine.bodies.missed < coarse.bodies.missed);
  check_self(coarse);
  check_self(fine);
  // Every discrete broad phase sees the same samples: the same misses.
  for (const char* m : {"sphere/sap", "aabb/grid", "aabb/hgrid", "aabb/rtree"}) {
    CAPTURE(m);
    CHECK(s.run(m, 0.1).bodies.missed == coarse.bodies.missed);
  }
}

TEST_CASE("study sap-coherence: swaps per step grow with dt, the first step is the one rebuild at a fine dt",
          "[studies]") {
  const Study s("rain", {{"bodies", 300}, {"seed", 1}, {"gravity", 100}, {"horizon", 1.5}});
  // sap (I-COLLIDE: endpoint swaps on three axes, pair set updated from them) and sweep
  // (insertion sort of starts on one axis, re-swept every step) keep a sorted order between
  // steps; the grid rebuilds a step unless its Verlet list serves it (`reuse=0`: every step).
  std::vector<double> sap_swaps_per_step, sweep_swaps_per_step;
  for (double dt : {0.003, 0.03, 0.3}) {
    CAPTURE(dt);
    const auto sap = s.run("aabb/sap", dt);
    const auto sweep = s.run("aabb/sweep", dt);
    const auto g = s.run("aabb/grid", dt);
    const auto plain = s.run("aabb/grid:reuse=0", dt);
    // The same boxes, the same pairs, whatever the coherence.
    CHECK(sap.bodies.candidates == g.bodies.candidates);
    CHECK(sweep.bodies.candidates == g.bodies.candidates);
    CHECK(sap.bodies.missed == g.bodies.missed);
    CHECK(sweep.bodies.missed == g.bodies.missed);
    for (const auto* r : {&sap, &sweep}) {
      CHECK(r->rebuilds >= 1);  // the first step builds
      CHECK(r->rebuilds <= r->steps);
      CHECK(counter(*r, "swaps") > 0);
      check_self(*r);
    }
    CHECK(plain.bodies.candidates == g.bodies.candidates);
    CHECK(plain.rebuilds == plain.steps);  // built anew every step
    CHECK(g.rebuilds >= 1);
    CHECK(g.rebuilds <= g.steps);
    CHECK(g.counters.empty());  // a grid has no counters of its own
    sap_swaps_per_step.push_back(double(counter(sap, "swaps")) / double(sap.steps));
    sweep_swaps_per_step.push_back(double(counter(sweep, "swaps")) / double(sweep.steps));
    if (dt == 0.003) {  // coherent: only the first build
      CHECK(sap.rebuilds == 1);
      CHECK(sweep.rebuilds == 1);
    }
    if (dt == 0.3) {  // balls cross much of the column per step: coherence lost
      CHECK(sap.rebuilds > 1);
      CHECK(sweep.rebuilds > 1);
    }
  }
  for (const auto* v : {&sap_swaps_per_step, &sweep_swaps_per_step}) {
    CHECK((*v)[0] < (*v)[1]);
    CHECK((*v)[1] < (*v)[2]);
  }
  // sap swaps endpoints (two per body) on three axes, sweep only starts on one axis: the
  // start/start reorderings sweep counts are among the swaps sap makes on that axis (up to
  // ties and different rebuild steps), so sap counts more (several times more here).
  for (std::size_t k = 0; k < sap_swaps_per_step.size(); ++k) CHECK(sap_swaps_per_step[k] > sweep_swaps_per_step[k]);
}

TEST_CASE("study equal-endpoints: every method finds every touching pair, strict comparisons find none",
          "[studies]") {
  // 4^3 spheres at rest, each exactly touching its lattice neighbours: 144 pairs.
  const Study s("lattice", {{"bodies", 64}, {"radius", 0.5}});
  REQUIRE(s.truth.events().size() == 144);
  for (const std::string& m : ccdlab::all_method_names()) {
    CAPTURE(m);
    const auto r = s.run(m, 0.5);
    // Every pair touches from t = 0 on: all 144 events are initial contacts, and every
    // method confirms every pair at every sample or step.
    CHECK(r.bodies.initial_contacts == 144);
    CHECK(r.bodies.missed == 0);
    CHECK(r.bodies.confirmed == 144 * r.steps);
    check_self(r);
  }
  // The same boxes (sphere boxes at t = 0, exact: centres and radii are dyadic) compared
  // with strict < instead of <=: touching boxes no longer overlap.
  std::vector<ccd::Aabb> boxes;
  for (const ccd::Body& b : s.scene.bodies) boxes.push_back(ccd::Aabb::around(b.position, b.radius));
  const std::size_t closed = count_box_pairs(boxes, false);
  const std::size_t strict = count_box_pairs(boxes, true);
  // Closed: the 26-neighbourhood, faces 3 * (3 * 4 * 4) + edges 6 * (3 * 3 * 4) + corners 4 * 27.
  CHECK(closed == 144 + 6 * 3 * 3 * 4 + 4 * 3 * 3 * 3);
  CHECK(strict < closed);
  CHECK(strict == 0);
}

TEST_CASE("study grazing: the truth reports tangent events, conservative methods detect them all",
          "[studies]") {
  // 32 pairs: 8 tangent, 8 one ulp beyond, 8 shallow crossings, 8 near misses; half of
  // each kind at closest-approach times k / 64.
  const Study s("grazing", {{"bodies", 64}, {"seed", 2}});
  std::size_t tangent = 0;
  for (const ccd::ContactEvent& e : s.truth.events()) tangent += e.enter == e.exit;
  CHECK(s.truth.events().size() == 16);  // one ulp beyond is a separation, as are near misses
  CHECK(tangent == 8);
  for (const std::string& m : kConservative)
    for (double dt : {0.25, 1.0 / 64, 0.01}) {
      CAPTURE(m, dt);
      const auto r = s.run(m, dt);
      CHECK(r.bodies.missed == 0);
      check_self(r);
    }
  // Discrete at dt = 1/64: every on-grid exact tangency and crossing is at a sample time
  // (4 + 4 detected); nothing off the grid (the crossings last 3.5e-4 s, a quarter tick
  // or more from any sample).
  const auto r = s.run("sphere/sap", 1.0 / 64);
  CHECK(r.bodies.detected >= 8);
  CHECK(r.bodies.detected <= 12);
  CHECK(s.run("sphere/sap", 0.01).bodies.detected < r.bodies.detected);
}

TEST_CASE("study precision: conservative methods miss nothing at offset 1e6", "[studies]") {
  const Study s("gas", {{"bodies", 300}, {"seed", 7}, {"offset", 1e6}});
  REQUIRE(s.truth.events().size() > 5);
  for (const std::string& m : kConservative) {
    CAPTURE(m);
    const auto r = s.run(m, 0.05);
    CHECK(r.bodies.missed == 0);
    check_self(r);
  }
}

TEST_CASE("study bound-violation: no misses at ratio >= 1, misses at 0.25", "[studies]") {
  const double A = 200.0;
  const Study s("swarm", {{"bodies", 300}, {"seed", 1}, {"max_acceleration", A}, {"fraction", 0.05}});
  REQUIRE(s.scene.max_acceleration() <= A);
  for (const char* m : {"horn:4/sap", "horn_sat:4/sap", "enclosing_sphere/grid"}) {
    CAPTURE(m);
    for (double ratio : {1.0, 1.5}) {
      CAPTURE(ratio);
      const auto r = s.run(m, 0.25, ratio * A);
      CHECK(r.bodies.missed == 0);
      check_self(r);
    }
    CHECK(s.run(m, 0.25, 0.25 * A).bodies.missed > 0);
  }
  CHECK(s.run("capsule/sap", 0.25, 0.25 * A).bodies.missed == 0);  // exact motion: A not used
}

TEST_CASE("study scheduling: @earliest misses nothing and detects what fixed steps detect", "[studies]") {
  struct Scene {
    const char* generator;
    json params;
  };
  for (const Scene& sc : {Scene{"gas", {{"bodies", 300}, {"seed", 1}, {"fraction", 0.002}, {"speed_max", 20}}},
                          Scene{"gas", {{"bodies", 200}, {"seed", 1}, {"fraction", 0.1}, {"speed_max", 20}}},
                          Scene{"bullets", {{"bodies", 200}, {"seed", 1}, {"bullets", 20}}},
                          Scene{"swarm", {{"bodies", 200}, {"seed", 1}, {"max_acceleration", 200}}}}) {
    const Study s(sc.generator, sc.params);
    CAPTURE(sc.params.dump());
    for (const char* m : {"capsule/grid", "horn:4/grid", "swept_aabb/grid", "enclosing_sphere/grid"}) {
      for (const double dt : {0.3, 0.03}) {
        CAPTURE(m, dt);
        const auto fixed = s.run(m, dt);
        const auto sched = s.run(std::string(m) + "@earliest", dt);
        CHECK(sched.bodies.missed == 0);
        CHECK(sched.bodies.detected == fixed.bodies.detected);
        check_self(sched);
        // A narrow call only where the bounds allow contact from the call on: never more
        // calls than the pair tests that passed.
        CHECK(sched.bodies.narrow_calls <= sched.bodies.passed);
        CHECK(sched.refreshes >= s.traj.size());
        const auto adapted = s.run(std::string(m) + "@earliest:reach=4", dt);  // speed-adapted windows
        CHECK(adapted.bodies.missed == 0);
        CHECK(adapted.bodies.detected == fixed.bodies.detected);
        check_self(adapted);
      }
    }
  }
}

TEST_CASE("study scheduling: a violated bound's earliest time costs misses", "[studies]") {
  // The swarm at acceleration_bound 0.25 x its true maximum (scheduling-violation): the
  // narrow phase started at the horn's earliest time misses contacts that the step start
  // still finds.
  const double A = 200.0;
  const Study s("swarm", {{"bodies", 300}, {"seed", 1}, {"max_acceleration", A}, {"fraction", 0.05}});
  const auto from_start = s.run("horn:4/grid", 0.25, 0.25 * A);
  const auto from_earliest = s.run("horn:4/grid@fixed:narrow_from_earliest=1", 0.25, 0.25 * A);
  const auto scheduled = s.run("horn:4/grid@earliest", 0.25, 0.25 * A);
  CHECK(from_start.bodies.missed > 0);
  CHECK(from_earliest.bodies.missed > from_start.bodies.missed);
  CHECK(scheduled.bodies.missed > 0);
  check_self(from_earliest);
  check_self(scheduled);
  // Assumption holding: the same detections either way.
  CHECK(s.run("horn:4/grid@fixed:narrow_from_earliest=1", 0.25, A).bodies.missed == 0);
  CHECK(s.run("horn:4/grid@earliest", 0.25, A).bodies.missed == 0);
}

TEST_CASE("study spinning: rotation alone tunnels through sampling, conservative bounds miss nothing", "[studies][rigid]") {
  // data/experiments/spinning.json, smaller: sticks and balls, no translation.
  const RigidStudy st("sticks", json{{"bodies", 160}, {"seed", 1}, {"speed_max", 0}, {"spin_max", 24},
                                     {"elongation", 16}, {"spheres", 0.5}, {"fraction", 0.1}, {"overlap", 1}});
  for (const ccd::Body& b : st.scene.bodies) REQUIRE(b.velocity.isZero(0.0));
  REQUIRE(st.truth.events().size() >= 20);
  std::uint64_t fine = 0, coarse = 0;
  for (const double dt : {1.0 / 512, 0.25}) {
    for (const char* m : {"sphere/sap", "aabb/sap", "frame_aabb/sap", "obb/sap"}) {
      const ccdlab::RunRecord r = st.run(m, dt);
      check_self(r);
      (dt == 0.25 ? coarse : fine) += r.bodies.missed;
    }
    for (const char* m : {"swept_aabb/sap", "capsule/sap", "obb_sat:1/sap", "obb_sat:4/sap", "obb_sat:4/sap@earliest"}) {
      INFO(m << " dt " << dt);
      const ccdlab::RunRecord r = st.run(m, dt);
      check_self(r);
      CHECK(r.conservative);
      CHECK(r.bodies.missed == 0);
    }
  }
  // Sampling at a quarter second misses contacts made by rotation alone, and more of them
  // than sampling 128 times as often.
  CHECK(coarse > 0);
  CHECK(coarse > fine);
}

TEST_CASE("study fit: orientation-aware bounds report fewer false positives on long bodies, at equal misses", "[studies][rigid]") {
  // data/experiments/fit-*.json, smaller: sticks of elongation 1 and 16.
  for (const double e : {1.0, 16.0}) {
    const RigidStudy st("sticks", json{{"bodies", 200}, {"seed", 1}, {"speed_max", 2}, {"spin_max", 4},
                                       {"elongation", e}, {"fraction", 0.1}});
    INFO("elongation " << e);
    const double dt = 1.0 / 60;
    const ccdlab::RunRecord sphere = st.run("sphere/sap", dt), aabb = st.run("aabb/sap", dt),
                            frame = st.run("frame_aabb/sap", dt), obb = st.run("obb/sap", dt),
                            swept = st.run("swept_aabb/sap", dt), sat = st.run("obb_sat:4/sap", dt);
    for (const ccdlab::RunRecord* r : {&sphere, &aabb, &frame, &obb, &swept, &sat}) check_self(*r);
    // Equal misses: every discrete bound holds the shape at the sample, so the exact sample
    // test decides; every continuous bound here is conservative.
    CHECK(aabb.bodies.missed == sphere.bodies.missed);
    CHECK(frame.bodies.missed == sphere.bodies.missed);
    CHECK(obb.bodies.missed == sphere.bodies.missed);
    CHECK(swept.bodies.missed == 0);
    CHECK(sat.bodies.missed == 0);
    // The turned shape's box lies inside the enclosing sphere's box.
    CHECK(frame.false_positives <= aabb.false_positives);
    if (e == 16.0) {
      CHECK(frame.false_positives < aabb.false_positives);
      CHECK(2 * obb.false_positives < sphere.false_positives);
      CHECK(2 * sat.false_positives < swept.false_positives);
    }
  }
}

TEST_CASE("study thin-obstacles: discrete methods pass through thin plates, conservative ones miss none",
          "[studies][scenery]") {
  // The study's scene (data/experiments/thin-obstacles.json: pinball, 100 obstacles, seed
  // 1) with 40 of its 200 balls over half a second (hundredths of a second in Release, so
  // the sanitizer build runs it whole).
  const ccd::Scene scene =
      ccdlab::generate_scene("pinball", json{{"bodies", 40}, {"obstacles", 100}, {"seed", 1}, {"horizon", 0.5}});
  const ccd::Trajectories traj(scene);
  const ccdlab::TruthIndex truth(ccd::compute_truth(traj));
  const std::vector<ccd::StaticEvent> events = ccd::compute_static_truth(traj, scene.scenery, 1);
  REQUIRE(events.size() > 5);
  ccdlab::RunInput in;
  in.scene = &scene;
  const ccd::RigidMotion scene_motion(scene, traj);
  in.motion = &scene_motion;
  in.truth = &truth;
  in.static_events = events;
  in.acceleration_bound = scene.max_acceleration();
  auto run = [&](const std::string& method, double dt) { return ccdlab::run_method(in, ccdlab::parse_method(method), dt); };
  CHECK(run("sphere/grid", 0.1).scenery.missed > 0);  // crossing a plate takes milliseconds
  for (const char* m : {"swept_aabb/grid", "capsule/grid", "horn:4/grid", "enclosing_sphere/grid"}) {
    INFO(m);
    CHECK(run(m, 0.1).scenery.missed == 0);
  }
  const ccdlab::RunRecord k = run("capsule/grid@fixed:kinematic=1", 0.1);
  CHECK(k.scenery.tests_saved > 0);
  CHECK(k.scenery.tests_saved <= k.scenery.passed);
  // The study's scheduled methods: no miss either, and static checks made per body window.
  for (const char* m : {"capsule/grid@earliest", "capsule/grid@earliest:reach=4", "horn:4/grid@earliest"}) {
    INFO(m);
    const ccdlab::RunRecord r = run(m, 0.1);
    CHECK(r.conservative);
    CHECK(r.scenery.missed == 0);
    CHECK(r.scenery.detected > 0);
    CHECK(r.self_check_unexpected == 0);
    CHECK(r.scenery.narrow_calls >= r.scenery.confirmed);
  }
}

}  // namespace experiments_studies_test
