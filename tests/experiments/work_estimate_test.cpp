// The certified pair estimate (experiments/work_estimate.hpp): candidate pairs enumerated,
// deep overlap apart from near passes, a pile of 300 spinning boxes refused while every
// scene and experiment shipped in data/ passes without --force.
#include "../../experiments/cloth_experiment.hpp"
#include "../../experiments/experiment.hpp"
#include "../../experiments/run_experiment.hpp"
#include "../../experiments/work_estimate.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace experiments_work_estimate_test {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const json kBox = {{"name", "crate"}, {"kind", "box"}, {"half_extents", {0.5, 0.3, 0.2}}};

json body(double x, double v, const json& spin, double y = 0.0) {
  return {{"shape", "crate"}, {"position", {x, y, 0}}, {"velocity", {v, 0, 0}}, {"angular_velocity", spin}};
}

// n boxes at one point, each spinning about its own axis (the pile of hostile_outputs_test.cpp).
ccd::Scene spinning_pile(int n) {
  json bodies = json::array();
  for (int i = 0; i < n; ++i)
    bodies.push_back(body(0, 0, {std::sin(i) * 5, std::cos(i * 1.7) * 5, std::sin(i * 0.3 + 1) * 5}));
  return ccd::scene_from_json({{"format", "ccdlab-scene/2"}, {"horizon", 1.0}, {"shapes", {kBox}}, {"bodies", bodies}},
                              "pile.json");
}

ccdlab::PairWork work_of(const ccd::Scene& s) {
  const ccd::Trajectories traj(s);
  return ccdlab::pair_window_work(ccd::RigidMotion(s, traj));
}

double truth_work(const ccd::Scene& s) {
  const ccd::Trajectories traj(s);
  return ccdlab::certified_pair_work(ccd::RigidMotion(s, traj));
}

// A box spinning at the origin and one at (x1, y1, 0) moving at v1 along x, spinning too.
ccd::Scene two_boxes(double x1, double v1, double y1 = 0.0) {
  return ccd::scene_from_json({{"format", "ccdlab-scene/2"},
                               {"horizon", 1.0},
                               {"shapes", {kBox}},
                               {"bodies", {body(0, 0, {0, 0, 3}), body(x1, v1, {3, 0, 0}, y1)}}},
                              "two.json");
}

}  // namespace

TEST_CASE("the certified pair estimate tells deep overlap from a passing contact", "[estimate]") {
  // Spinning inside each other all along: deep in each of the 16 windows, nothing near.
  const ccdlab::PairWork pile = work_of(two_boxes(0.0, 0.0));
  CHECK(pile.near == 0.0);
  // (1 + turn_a + turn_b) (8 + 8) per window, turn = |omega| R / R x 1/16 each.
  CHECK(pile.deep == Approx(16 * (1.0 + 2 * 3.0 / 16) * 16));
  // One box passing 0.5 m beside the other at 4 m/s (more than the inner radii, 0.2 + 0.2,
  // apart): candidates near the meeting only, never deep, and far cheaper for the truth.
  const ccd::Scene passing_scene = two_boxes(-2.0, 4.0, 0.5);
  const ccdlab::PairWork passing = work_of(passing_scene);
  CHECK(passing.deep == 0.0);
  CHECK(passing.near > 0.0);
  CHECK(truth_work(passing_scene) * 50 < truth_work(two_boxes(0.0, 0.0)));
  // Far apart: no candidate pair at all.
  const ccdlab::PairWork apart = work_of(two_boxes(100.0, 0.0));
  CHECK(apart.near == 0.0);
  CHECK(apart.deep == 0.0);
}

TEST_CASE("a pile of 300 spinning boxes is refused, and the piles the estimate was calibrated on bracket the limit",
          "[estimate]") {
  CHECK(truth_work(spinning_pile(300)) > 100 * ccdlab::kMaxPairWorkWithoutForce);  // hours
  CHECK(truth_work(spinning_pile(40)) > ccdlab::kMaxPairWorkWithoutForce);         // 13 minutes measured
  CHECK(truth_work(spinning_pile(20)) < ccdlab::kMaxPairWorkWithoutForce);         // 98 s measured
  CHECK(truth_work(spinning_pile(2)) < 1e7);
}

TEST_CASE("every scene and experiment shipped in data/ passes the work estimates without --force", "[estimate]") {
  const fs::path data = fs::path(CCDLAB_SOURCE_DIR) / "data";
  int scenes = 0, experiments = 0, shaped = 0;
  for (const auto& f : fs::directory_iterator(data / "scenes")) {
    if (f.path().extension() != ".json") continue;
    INFO(f.path().string());
    const ccd::Scene s = ccd::load_scene(f.path().string());
    ++scenes;
    if (!s.has_non_spheres()) continue;
    ++shaped;
    CHECK(truth_work(s) <= ccdlab::kMaxPairWorkWithoutForce);
  }
  for (const auto& f : fs::directory_iterator(data / "experiments")) {
    const std::string path = f.path().string();
    if (f.path().extension() != ".json" || ccdlab::is_cloth_experiment(ccd::read_json_file(path))) continue;
    INFO(path);
    const ccdlab::Experiment e = ccdlab::load_experiment(path);
    const ccd::Scene s = ccdlab::load_experiment_scene(e, path);
    ++experiments;
    CHECK(ccdlab::experiment_work(e, s.bodies.size(), s.horizon) <= ccdlab::kMaxWorkWithoutForce);
    if (!s.has_non_spheres()) continue;
    ++shaped;
    const ccd::Trajectories traj(s);
    const double steps = ccdlab::experiment_work(e, 1, s.horizon);
    CHECK(ccdlab::run_pair_work(ccd::RigidMotion(s, traj), steps, false) <= ccdlab::kMaxPairWorkWithoutForce);
  }
  CHECK(scenes >= 3);
  CHECK(experiments >= 40);
  CHECK(shaped >= 10);
}

}  // namespace experiments_work_estimate_test
