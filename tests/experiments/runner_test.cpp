// The runner against hand-checked scenes: counts, lags and penetrations worked out by hand.
#include "../../experiments/runner.hpp"

#include <ccd/truth/ground_truth.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

namespace experiments_runner_test {

using ccd::Vec3;
using ccdlab::parse_method;
using ccdlab::run_method;

namespace {

// Two spheres of radius 0.5 approach head-on at relative speed 2 from 10 apart: their
// centres are within 1 of each other exactly for t in [4.5, 5.5] (they pass through).
ccd::Scene head_on() {
  ccd::Scene s;
  s.horizon = 10.0;
  s.bodies.push_back({0.5, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(10, 0, 0), Vec3(-1, 0, 0), Vec3::Zero(), {}});
  return s;
}

struct Fixture {
  ccd::Scene scene;
  ccd::Trajectories traj;
  ccdlab::TruthIndex truth;
  explicit Fixture(ccd::Scene s)
      : scene(std::move(s)), traj(scene), truth(ccd::compute_truth(traj)) {}
  ccdlab::RunRecord run(const std::string& method, double dt, double A = 0.0) const {
    ccdlab::RunInput in;
    in.scene = &scene;
    const ccd::RigidMotion scene_motion(scene, traj);
    in.motion = &scene_motion;
    in.truth = &truth;
    in.acceleration_bound = A;
    return run_method(in, parse_method(method), dt);
  }
};

constexpr double eps = std::numeric_limits<double>::epsilon();

}  // namespace

TEST_CASE("head-on pair: the truth is one event [4.5, 5.5]", "[runner]") {
  const Fixture f(head_on());
  REQUIRE(f.truth.events().size() == 1);
  CHECK(f.truth.events()[0].enter == Approx(4.5).epsilon(1e-12));
  CHECK(f.truth.events()[0].exit == Approx(5.5).epsilon(1e-12));
}

TEST_CASE("discrete methods at a coarse dt tunnel, at a fine dt they detect", "[runner]") {
  const Fixture f(head_on());
  SECTION("dt = 2: samples 0, 2, 4, 6, 8, 10 all miss [4.5, 5.5]") {
    const auto r = f.run("aabb/brute", 2.0);
    CHECK(r.steps == 6);
    CHECK(r.bodies.events == 1);
    CHECK(r.bodies.detected == 0);
    CHECK(r.bodies.missed == 1);
    CHECK(r.bodies.candidates == 0);
    CHECK(r.self_check_unexpected == 0);
    CHECK(r.self_check_undetected == 0);
  }
  SECTION("dt = 1: detected at t = 5, centres coincide: lag 0.5, penetration 1") {
    const auto r = f.run("sphere/brute", 1.0);
    CHECK(r.steps == 11);
    CHECK(r.bodies.detected == 1);
    CHECK(r.bodies.missed == 0);
    CHECK(r.mean_lag == Approx(0.5).epsilon(1e-9));
    CHECK(r.max_penetration == Approx(1.0).epsilon(8 * eps));
    CHECK(r.bodies.confirmed == 1);  // only the sample t = 5 is inside the event
    CHECK(r.self_check_undetected == 0);
  }
  SECTION("dt = 0.5: detected at t = 4.5 exactly, touching: lag 0, penetration 0") {
    const auto r = f.run("aabb/brute", 0.5);
    CHECK(r.bodies.detected == 1);
    CHECK(r.mean_lag == Approx(0.0).margin(1e-9));
    CHECK(r.max_penetration == Approx(0.0).margin(1e-12));
    CHECK(r.bodies.confirmed == 3);  // samples 4.5, 5.0, 5.5
  }
}

TEST_CASE("continuous methods catch the tunnelling pair at every dt", "[runner]") {
  const Fixture f(head_on());
  for (const char* m : {"swept_aabb/brute", "capsule/brute"}) {
    for (double dt : {10.0, 3.0, 2.0, 0.7}) {
      INFO(m << " dt=" << dt);
      const auto r = f.run(m, dt);
      CHECK(r.bodies.detected == 1);
      CHECK(r.bodies.missed == 0);
      CHECK(r.mean_lag == Approx(0.0).margin(1e-9));
      CHECK(r.self_check_unexpected == 0);
    }
  }
  SECTION("the last partial step counts: dt = 3 gives steps [0,3] [3,6] [6,9] [9,10]") {
    CHECK(f.run("capsule/brute", 3.0).steps == 4);
  }
}

TEST_CASE("a bounded bound with a too-small acceleration bound misses, and says so", "[runner]") {
  // Body 1 accelerates towards body 0 at 2 m/s^2 from rest 3 apart (gap 2): contact when
  // t^2 = 2, t = sqrt(2). With A = 0 the horn is a capsule along the (zero) velocity.
  ccd::Scene s;
  s.horizon = 2.0;
  s.bodies.push_back({0.5, Vec3(0, 0, 0), Vec3::Zero(), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(3, 0, 0), Vec3::Zero(), Vec3(-2, 0, 0), {}});
  const Fixture f(s);
  REQUIRE(f.truth.events().size() == 1);
  CHECK(f.truth.events()[0].enter == Approx(std::sqrt(2.0)).epsilon(1e-12));
  CHECK(f.run("horn:4/brute", 2.0, 0.0).bodies.missed == 1);
  CHECK(f.run("horn:4/brute", 2.0, 2.0).bodies.missed == 0);
  CHECK(f.run("enclosing_sphere/brute", 2.0, 2.0).bodies.missed == 0);
}

TEST_CASE("a record stores the options it ran with and the broad phase's counters", "[runner]") {
  const Fixture f(head_on());
  const ccdlab::RunRecord plain = f.run("horn:2/grid", 0.25);
  const ccdlab::RunRecord set = f.run("horn:pieces=3/grid:cell=3,threads=2", 0.25);
  CHECK(plain.options == nlohmann::json{{"bound", {{"pieces", 2}}},
                                        {"broad_phase", {{"cell", 0.0}, {"reuse", 32}, {"threads", 1}}}});
  CHECK(set.options == nlohmann::json{{"bound", {{"pieces", 3}}},
                                      {"broad_phase", {{"cell", 3.0}, {"reuse", 32}, {"threads", 2}}}});
  // The grid is exact whatever its cell: the same pairs, the same detection.
  CHECK(set.bodies.candidates == plain.bodies.candidates);
  CHECK(set.bodies.detected == plain.bodies.detected);
  CHECK(plain.counters.empty());  // the grid has no counters of its own
  const ccdlab::RunRecord sap = f.run("aabb/sap", 0.25);
  REQUIRE(sap.counters.size() == 1);
  CHECK(sap.counters[0].first == "swaps");
  CHECK(sap.counters[0].second > 0);  // the pair passes each other: endpoints swap
  CHECK(ccdlab::to_json(sap)["counters"] == nlohmann::json{{"swaps", sap.counters[0].second}});
  CHECK(ccdlab::to_json(set)["options"] == set.options);
}

TEST_CASE("the sample set is every t_k = k * dt (the double product) with t_k <= T", "[runner]") {
  // 43 * 0.1 == 4.3 in double although floor(4.3 / 0.1) == 42: the sample at T is taken.
  REQUIRE(43 * 0.1 == 4.3);
  REQUIRE(std::floor(4.3 / 0.1) == 42.0);
  CHECK(ccdlab::sample_count(4.3, 0.1) == 44);
  CHECK(ccdlab::sample_count(1.0, 0.1) == 11);       // 10 * 0.1 == 1.0
  CHECK(ccdlab::sample_count(1.0, 1.0 / 3) == 4);    // 3 * (1/3) == 1.0
  CHECK(ccdlab::sample_count(0.7, 0.1) == 7);        // 7 * 0.1 > 0.7: k = 0..6
  CHECK(ccdlab::sample_count(1.0, 2.0) == 1);        // only t = 0
  CHECK(ccdlab::sample_count(1.0, 0.0) == 0);
  for (double dt : {0.1, 0.3, 0.7, 1.0 / 3, 1e-3, 0.0123}) {
    CAPTURE(dt);
    const std::uint64_t n = ccdlab::sample_count(4.3, dt);
    CHECK(double(n - 1) * dt <= 4.3);
    CHECK(double(n) * dt > 4.3);
  }
  // A tangency exactly at T = 4.3 is seen by a discrete method at its last sample.
  ccd::Scene s;
  s.horizon = 4.3;
  s.bodies.push_back({0.5, Vec3(0, 0, 0), Vec3::Zero(), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(-4.3, 1, 0), Vec3(1, 0, 0), Vec3::Zero(), {}});
  const Fixture f(s);
  REQUIRE(f.truth.events().size() == 1);
  CHECK(f.truth.events()[0].enter == 4.3);
  CHECK(f.truth.events()[0].exit == 4.3);
  const auto r = f.run("sphere/brute", 0.1);
  CHECK(r.steps == 44);
  CHECK(r.bodies.missed == 0);
  CHECK(r.self_check_unexpected == 0);
  CHECK(f.run("capsule/brute", 0.1).bodies.missed == 0);
}

TEST_CASE("events in progress at t = 0 are counted apart from misses, lag and penetration", "[runner]") {
  // Pair (0, 1) overlaps by 0.5 at t = 0 and separates; pair (2, 3) meets head-on later.
  ccd::Scene s;
  s.horizon = 10.0;
  s.bodies.push_back({0.5, Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(0, 100, 0), Vec3(1, 0, 0), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(10, 100, 0), Vec3(-1, 0, 0), Vec3::Zero(), {}});
  const Fixture f(s);
  REQUIRE(f.truth.events().size() == 2);
  SECTION("a discrete method that tunnels the later event") {
    const auto r = f.run("sphere/brute", 2.0);
    CHECK(r.bodies.events == 2);
    CHECK(r.bodies.initial_contacts == 1);
    CHECK(r.bodies.detected == 0);
    CHECK(r.bodies.missed == 1);
    CHECK(r.max_penetration == 0.0);  // the initial overlap of 0.5 does not count
  }
  SECTION("a continuous method: zero depth, zero lag") {
    const auto r = f.run("capsule/brute", 2.0);
    CHECK(r.bodies.initial_contacts == 1);
    CHECK(r.bodies.detected == 1);
    CHECK(r.bodies.missed == 0);
    CHECK(r.max_penetration <= 4 * eps);
    CHECK(r.max_lag == 0.0);
  }
  const nlohmann::json j = ccdlab::to_json(f.run("sphere/brute", 2.0));
  CHECK(j["initial_contacts"] == 1);
  CHECK(j["missed_fraction"] == 1.0);  // 1 missed of the 1 event not in progress at t = 0
}

namespace {

// Four head-on pairs of radius-0.5 spheres, 10 apart in y, each pair closing at relative
// speed 2 from centres at -s and +s: in contact exactly for t in [s - 0.5, s + 0.5].
// s = 7, 1.75, 3, 5.5 for bodies (0, 1), (2, 3), (4, 5), (6, 7).
ccd::Scene four_pairs() {
  ccd::Scene sc;
  sc.horizon = 10.0;
  const double s[] = {7.0, 1.75, 3.0, 5.5};
  for (int p = 0; p < 4; ++p) {
    sc.bodies.push_back({0.5, Vec3(-s[p], 10.0 * p, 0), Vec3(1, 0, 0), Vec3::Zero(), {}});
    sc.bodies.push_back({0.5, Vec3(s[p], 10.0 * p, 0), Vec3(-1, 0, 0), Vec3::Zero(), {}});
  }
  return sc;
}

}  // namespace

TEST_CASE("list_missed: the missed events are the truth events no sample falls in, by enter time", "[runner]") {
  const Fixture f(four_pairs());
  REQUIRE(f.truth.events().size() == 4);
  ccdlab::RunInput in;
  in.scene = &f.scene;
  const ccd::RigidMotion scene_motion(f.scene, f.traj);
  in.motion = &scene_motion;
  in.truth = &f.truth;
  in.list_missed = true;
  // Samples 0, 2, 4, 6, 8, 10: [1.25, 2.25] holds 2 and [5, 6] holds 6; [2.5, 3.5] and
  // [6.5, 7.5] hold none.
  const auto r = run_method(in, parse_method("aabb/sap"), 2.0);
  CHECK(r.bodies.missed == 2);
  REQUIRE(r.bodies.missed_events.size() == 2);
  CHECK(r.bodies.missed_events[0].a == 4);
  CHECK(r.bodies.missed_events[0].b == 5);
  CHECK(r.bodies.missed_events[0].enter == Approx(2.5).epsilon(1e-12));
  CHECK(r.bodies.missed_events[0].exit == Approx(3.5).epsilon(1e-12));
  CHECK(r.bodies.missed_events[1].a == 0);
  CHECK(r.bodies.missed_events[1].b == 1);
  CHECK(r.bodies.missed_events[1].enter == Approx(6.5).epsilon(1e-12));
  const auto j = ccdlab::to_json(r, true);
  REQUIRE(j["missed_events"].size() == 2);
  CHECK(j["missed_events"][0]["a"] == 4);
  CHECK(j["missed_events"][1]["enter"].get<double>() == r.bodies.missed_events[1].enter);
  CHECK_FALSE(ccdlab::to_json(r, false).contains("missed_events"));
  // Every event missed at a dt that skips them all, none by a conservative bound.
  CHECK(run_method(in, parse_method("aabb/sap"), 4.0).bodies.missed_events.size() == 4);  // samples 0, 4, 8: in none
  CHECK(run_method(in, parse_method("capsule/sap"), 4.0).bodies.missed_events.empty());
  // Without the option the list stays empty.
  in.list_missed = false;
  CHECK(run_method(in, parse_method("aabb/sap"), 2.0).bodies.missed_events.empty());
}

TEST_CASE("conservative in records: the guarantee as the method ran", "[runner]") {
  ccd::Scene s = head_on();
  s.gravity = Vec3(0, -8, 0);  // largest acceleration 8
  const Fixture f(s);
  CHECK_FALSE(f.run("aabb/grid", 0.5, 8.0).conservative);    // discrete: samples only
  CHECK_FALSE(f.run("sphere/brute", 0.5, 8.0).conservative);
  CHECK(f.run("capsule/grid", 0.5, 8.0).conservative);       // knows the exact motion
  CHECK(f.run("horn:4/grid", 0.5, 8.0).conservative);        // A = the scene's largest
  CHECK_FALSE(f.run("horn:4/grid", 0.5, 4.0).conservative);  // A below it: no guarantee
  CHECK(f.run("aabb/grid", 0.25, 8.0).hz == 4.0);
}

TEST_CASE("records carry the CPU time of the method's work beside its wall time", "[runner]") {
  const Fixture f(head_on());
  // Small steps so that the run takes measurable CPU time; a fixed and a scheduled method.
  for (const char* method : {"capsule/brute", "capsule/brute@earliest"}) {
    INFO(method);
    const ccdlab::RunRecord r = f.run(method, 1.0 / 4096.0);
    CHECK(r.cpu_seconds > 0.0);
    // One thread cannot use more CPU than wall time (clock granularity aside).
    CHECK(r.cpu_seconds <= r.total_seconds + 1e-3);
    CHECK(r.cpu_seconds_per_simulated_second == r.cpu_seconds / f.scene.horizon);
    const nlohmann::json j = ccdlab::to_json(r);
    CHECK(j["cpu_seconds"] == r.cpu_seconds);
    CHECK(j["cpu_seconds_per_simulated_second"] == r.cpu_seconds_per_simulated_second);
  }
}

}  // namespace experiments_runner_test
