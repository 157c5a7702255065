#pragma once
// Runs a cloth experiment (docs/experiments.md#cloth-experiments): simulates the scene once,
// computes (or reads back) its exact mesh truth (cloth/truth/mesh_truth.hpp), then runs every
// (culler, mode, k) job and measures it against the truth's contact events.
//
// A job checks the motion every k integrator steps (h each, so dt = k h):
//  - discrete: at every check state x_c, c = 0, k, 2k, ... <= S, the culler's candidates
//    of that one state (x1 = x0) go to the kernel (triangle_ccd, proximity within the
//    thickness d). An event (a pair in contact over steps first..last) is detected when
//    its pair is confirmed at a check state c in [first, last + 1] at which it is a truth
//    contact. A confirmed pair that is not a truth contact of that state is a false positive.
//  - continuous: over each check interval [c, c + k] (the last one shorter when k does not
//    divide S) the method only knows the two check states and assumes linear motion between
//    them. The true motion is linear per step, so it departs from that chord by at most D
//    (the largest distance of an intermediate state's vertex from the chord; 0 for k = 1).
//    Every point of a primitive then departs by at most D, so a true contact within d is a
//    chord contact within d + 2D: the culler and the kernel run on the chord motion with
//    separation d + 2D (plus margins above every rounding error). A conservative culler
//    therefore misses nothing. An event is detected when its pair is confirmed in the check
//    interval containing its first step; a confirmed pair with no truth contact in the
//    interval's steps is a false positive.
// Counts do not depend on the thread count.
#include "cloth_experiment.hpp"

#include <cloth/cull/cullers.hpp>
#include <cloth/sim/cloth_mesh.hpp>
#include <cloth/truth/mesh_truth.hpp>

#include <atomic>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ccdlab {

/// A simulated cloth run and its truth.
struct ClothMotion {
  ccd::cloth::ClothScene scene;
  ccd::cloth::ClothMesh mesh;
  std::vector<std::vector<ccd::Vec3>> frames;  ///< steps + 1 states
  ccd::cloth::MeshTruth truth;
  std::vector<ccd::cloth::MeshContactEvent> events;
  std::string digest;           ///< motion_digest of the run
  double truth_seconds = 0.0;   ///< computing (or reading) the truth
  std::string truth_file;       ///< where the truth was read from or stored ("" when not cached)
  bool truth_reused = false;    ///< read from truth_file
};

/// Simulates `scene` and computes its truth on `threads` threads. With a non-empty
/// `truth_cache` folder, the truth is read from FOLDER/DIGEST.json when that file exists,
/// else computed and stored there (atomically). Throws ccd::InputError for a bad cache file.
/// A set `cancel` stops the truth early: the motion is then incomplete and nothing is stored.
ClothMotion prepare_cloth_motion(const ccd::cloth::ClothScene& scene, unsigned threads,
                                 const std::string& truth_cache = "", const std::atomic<bool>* cancel = nullptr);

struct ClothRecord {
  std::string method;       ///< CULLER/MODE, e.g. "bvh/continuous"
  std::string culler;
  bool continuous = false;
  bool conservative = false;  ///< continuous with a culler that never drops a pair: zero misses expected
  int k = 1;                  ///< check interval, integrator steps
  double dt = 0.0;            ///< k h, seconds
  double hz = 0.0;            ///< 1 / dt
  std::uint64_t checks = 0;   ///< check states (discrete) or intervals (continuous)
  std::uint64_t events = 0;   ///< truth events
  std::uint64_t detected = 0;
  std::uint64_t missed = 0;
  std::uint64_t candidates = 0;    ///< culler output, summed over checks
  std::uint64_t narrow_calls = 0;  ///< kernel calls (one per candidate)
  std::uint64_t confirmed = 0;     ///< kernel hits
  std::uint64_t false_positives = 0;
  double max_separation = 0.0;     ///< largest separation given to culler and kernel (continuous: d + 2D)
  double cull_seconds = 0.0;       ///< medians over the repeats
  double narrow_seconds = 0.0;
  double total_seconds = 0.0;
  double seconds_per_simulated_second = 0.0;
  bool counts_stable = true;
  bool cancelled = false;
};

/// Runs one job. `culler` from the registry; 1 <= k <= steps.
ClothRecord run_cloth_method(const ClothMotion& motion, const ccd::cloth::CullerEntry& culler, bool continuous, int k,
                             int repeats = 1, const std::atomic<bool>* cancel = nullptr);

nlohmann::json to_json(const ClothRecord& r);

struct ClothRunOptions {
  int threads = 1;
  bool quiet = false;
  std::string truth_cache;  ///< folder of cached truths ("" : compute, do not store)
  const std::atomic<bool>* cancel = nullptr;
};

/// Runs the experiment; a `ccdlab-cloth-results/1` document, or null if cancelled.
nlohmann::json run_cloth_experiment(const ClothExperiment& e, const ccd::cloth::ClothScene& scene,
                                    const ClothRunOptions& options);

}  // namespace ccdlab
