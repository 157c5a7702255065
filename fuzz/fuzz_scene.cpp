// The scene reader, and what a run does with an accepted scene: trajectories, the exact
// ground truth, every broad phase over the bodies' swept boxes (checked against brute
// force), and the write/read round trip. Small scenes only go past the reader (the work
// of a scene of many bodies would slow the fuzzer down, not find more).
#include "fuzz_support.hpp"

#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/ground_truth.hpp>

#include <algorithm>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccd::Scene scene;
  try {
    scene = ccd::scene_from_json(ccd::parse_json_text(ccdfuzz::as_text(data, size), "fuzz.json"), "fuzz.json");
  } catch (const ccd::InputError&) {
    return 0;
  }
  // Written and read back: the same scene, bit for bit.
  const ccd::Scene again = ccd::scene_from_json(ccd::parse_json_text(ccd::scene_to_json(scene).dump(), "again"), "again");
  FUZZ_CHECK(ccd::scene_digest(again) == ccd::scene_digest(scene));
  if (scene.bodies.size() > 8) return 0;

  ccd::TrajectoryOptions options;
  options.max_pieces_per_body = 2000;
  ccd::Trajectories motion;
  try {
    motion = ccd::Trajectories(scene, options);
  } catch (const ccd::TooManyPieces&) {
    return 0;
  }
  ccd::TruthOptions truth;
  truth.threads = 1;
  const std::vector<ccd::ContactEvent> events = ccd::compute_truth(motion, truth);
  for (const ccd::ContactEvent& e : events) {
    FUZZ_CHECK(e.a < e.b && e.b < scene.bodies.size());
    FUZZ_CHECK(0.0 <= e.enter && e.enter <= e.exit && e.exit <= scene.horizon);
  }
  // Bodies stay in the box (between its walls: an axis that wraps around has none).
  if (scene.box)
    for (std::size_t i = 0; i < motion.size(); ++i)
      for (const ccd::Piece& p : motion.pieces(i))
        for (double t : {p.t0, p.t1}) {
          const ccd::Vec3 x = p.position(t);
          for (int k = 0; k < 3; ++k) {
            if (scene.box->wraps(k)) continue;
            const double slack = 1e-6 * (scene.box->max[k] - scene.box->min[k]);
            FUZZ_CHECK(x[k] >= scene.box->min[k] + motion.radius(i) - slack);
            FUZZ_CHECK(x[k] <= scene.box->max[k] - motion.radius(i) + slack);
          }
        }
  // Every broad phase on the swept boxes of a few windows finds the pairs brute force finds.
  const double T = scene.horizon;
  for (const auto& [u0, u1] : {std::pair{0.0, T}, std::pair{0.0, T / 3}, std::pair{T / 2, T / 2}}) {
    std::vector<ccd::Aabb> boxes;
    for (std::size_t i = 0; i < motion.size(); ++i) boxes.push_back(motion.swept_bounds(i, u0, u1));
    std::vector<ccd::BodyPair> reference, pairs;
    ccd::find_broad_phase("brute").make()->find_pairs(boxes, reference);
    auto order = [](const ccd::BodyPair& x, const ccd::BodyPair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
    std::sort(reference.begin(), reference.end(), order);
    for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
      auto broad = info.make();
      for (int frame = 0; frame < 2; ++frame) {  // the second frame exercises the incremental update
        broad->find_pairs(boxes, pairs);
        std::sort(pairs.begin(), pairs.end(), order);
        FUZZ_CHECK(pairs.size() == reference.size());
        for (std::size_t k = 0; k < pairs.size(); ++k)
          FUZZ_CHECK(pairs[k].a == reference[k].a && pairs[k].b == reference[k].b);
      }
    }
  }
  return 0;
}
