// compute_truth, the one truth call: sphere scenes equal the all-pairs reference with no
// error fields, progress counts every candidate run once, the cancel flag stops it, and a
// scene that mixes spheres, shapes and scenery gets each pair from its table entry.
#include <ccd/truth/truth.hpp>

#include "../scene/rigid_scenes.hpp"

#include <ccd/truth/truth_table.hpp>
#include <tests/ccd/scene/body_builder.hpp>

#include <atomic>
#include <catch2/catch.hpp>
#include <random>

namespace ccd_truth_truth_test {

using ccd::Scene;
using ccd::Vec3;

namespace {

Scene gas(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.horizon = 2.0;
  s.box = ccd::WallBox{Vec3::Zero(), Vec3::Constant(10.0)};
  for (int i = 0; i < n; ++i)
    s.bodies.push_back(ccd::test::body(0.3, {0.5 + 9 * u(rng), 0.5 + 9 * u(rng), 0.5 + 9 * u(rng)},
                                       {8 * u(rng) - 4, 8 * u(rng) - 4, 8 * u(rng) - 4}));
  return s;
}

}  // namespace

TEST_CASE("compute_truth of a sphere scene is the all-pairs reference, exact", "[truth]") {
  const Scene s = gas(5, 120);
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  const ccd::Truth t = ccd::compute_truth(motion, {});
  const std::vector<ccd::ContactEvent> ref = ccd::compute_truth_all_pairs(traj);
  REQUIRE(ref.size() > 20);
  CHECK(t.events == ref);
  CHECK(t.errors.empty());  // exact: no error fields
  CHECK_FALSE(t.has_scenery);
  CHECK(t.static_events.empty());
  CHECK(t.horizon == s.horizon);
  CHECK(t.scene_sha256.empty());  // the caller sets the digest
  CHECK_FALSE(t.stats.cancelled);
}

TEST_CASE("compute_truth reports progress over every candidate run and stops when cancelled", "[truth]") {
  const Scene s = gas(6, 150);
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  const ccd::Truth full = ccd::compute_truth(motion, {});
  REQUIRE(full.stats.candidate_runs > 100);
  SECTION("progress: increasing, ending at the total of candidate runs") {
    ccd::TruthOptions o;
    o.threads = 2;
    std::size_t last = 0, total = 0, calls = 0;
    bool increasing = true;
    o.progress = [&](std::size_t done, std::size_t all) {
      increasing = increasing && done > last;
      last = done;
      total = all;
      ++calls;
    };
    const ccd::Truth t = ccd::compute_truth(motion, {}, o);
    CHECK(t.events == full.events);
    CHECK(increasing);
    CHECK(calls > 1);
    CHECK(total == full.stats.candidate_runs);
    CHECK(last == total);
  }
  SECTION("a flag set before the call: nothing solved") {
    std::atomic<bool> cancel{true};
    ccd::TruthOptions o;
    o.cancel = &cancel;
    const ccd::Truth t = ccd::compute_truth(motion, {}, o);
    CHECK(t.stats.cancelled);
    CHECK(t.events.empty());
  }
  SECTION("a flag set part way: the rest is not solved") {
    std::atomic<bool> cancel{false};
    ccd::TruthOptions o;
    o.threads = 1;
    o.cancel = &cancel;
    o.progress = [&](std::size_t, std::size_t) { cancel = true; };  // after the first chunk
    const ccd::Truth t = ccd::compute_truth(motion, {}, o);
    CHECK(t.stats.cancelled);
    CHECK(t.events.size() < full.events.size());
  }
}

TEST_CASE("compute_truth of a mixed scene takes each pair from its table entry", "[truth][rigid][scenery]") {
  // The spinning stick through a resting ball (rigid_scenes.hpp), a second ball that the
  // first one meets, and a floor polygon under both balls.
  Scene s = ccd::test::spinning_stick_scene(M_PI, 2.0);
  REQUIRE(s.bodies.size() == 2);
  const Vec3 p = s.bodies[1].position;
  const double r = s.bodies[1].radius;  // 1/8
  // Centre distance 9/4 - 2t reaches 2r = 1/4 at t = 1 exactly.
  s.add_rigid_body(ccd::test::body(r, p + Vec3(0, 0, 2.25), {0, 0, -2}), ccd::RigidBody{});
  // The floor y = 3/4 - 1/8: both balls touch it (tangent) all the time; the stick crosses it.
  const double y = p.y() - r;
  s.scenery.push_back(ccd::polygon_from_vertices({Vec3(-3, y, -3), Vec3(3, y, -3), Vec3(3, y, 7), Vec3(-3, y, 7)}));
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  const ccd::Truth t = ccd::compute_truth(motion, s.scenery);
  REQUIRE(t.errors.size() == t.events.size());
  bool sphere_pair = false, stick_pair = false;
  for (std::size_t i = 0; i < t.events.size(); ++i) {
    if (t.events[i].a == 1 && t.events[i].b == 2) {  // two balls: exact, errors 0
      sphere_pair = true;
      CHECK(t.errors[i] == ccd::EventError{});
      CHECK(t.events[i].enter == 1.0);
    }
    if (t.events[i].a == 0 && t.events[i].b == 1) {  // the stick: certified brackets
      stick_pair = true;
      CHECK(t.errors[i].enter_error > 0.0);
    }
  }
  CHECK(sphere_pair);
  CHECK(stick_pair);
  // The balls touch the floor over the whole horizon: exact static events [0, 2] with no
  // error; the spinning stick's static events are certified brackets.
  CHECK(t.has_scenery);
  REQUIRE(t.static_errors.size() == t.static_events.size());
  int balls = 0, stick = 0;
  for (std::size_t i = 0; i < t.static_events.size(); ++i) {
    const ccd::StaticEvent& e = t.static_events[i];
    if (e.body == 0) {
      ++stick;
      CHECK(t.static_errors[i].enter_error + t.static_errors[i].exit_error > 0.0);
    } else {
      ++balls;
      CHECK(e.enter == 0.0);
      CHECK(e.exit == 2.0);
      CHECK(t.static_errors[i] == ccd::EventError{});
    }
  }
  CHECK(balls == 2);
  CHECK(stick > 0);
}

TEST_CASE("truth table: the default entries, the bracket table, a missing entry", "[truth]") {
  using K = ccd::ShapeKind;
  const ccd::TruthTable& t = ccd::truth_table();
  CHECK(t.find(K::Sphere, K::Sphere) == &ccd::exact_sphere_pair_truth);
  CHECK(t.find(K::Sphere, K::Box) == &ccd::bracket_pair_truth);
  CHECK(t.find(K::Box, K::Sphere) == &ccd::bracket_pair_truth);
  CHECK(t.find(K::Capsule, K::Hull) == &ccd::bracket_pair_truth);
  CHECK(t.find_polygon(K::Sphere) == &ccd::exact_sphere_polygon_truth);
  CHECK(t.find_polygon(K::Box) == &ccd::bracket_polygon_truth);
  CHECK(ccd::bracket_truth_table().find(K::Sphere, K::Sphere) == &ccd::bracket_pair_truth);
  CHECK(ccd::bracket_truth_table().find_polygon(K::Sphere) == &ccd::bracket_polygon_truth);
  const ccd::TruthTable empty;
  CHECK_THROWS_AS(empty.find(K::Sphere, K::Box), std::logic_error);
  CHECK_THROWS_AS(empty.find_polygon(K::Capsule), std::logic_error);
}

}  // namespace ccd_truth_truth_test
