#pragma once
// Runs a whole experiment: loads or generates the scene, computes the ground truth once,
// runs every (method, dt) job on a pool of threads, and assembles a `ccdlab-results/2`
// document (docs/experiments.md). Counts do not depend on the thread count: every job is
// independent and results are stored by job index.
#include "experiment.hpp"
#include "progress.hpp"

#include <ccd/scene/scene.hpp>
#include <ccd/truth/truth_io.hpp>

#include <atomic>
#include <nlohmann/json.hpp>
#include <string>

namespace ccdlab {

struct Shard {
  int index = 1;  ///< 1-based K of K/N
  int count = 1;  ///< N
  bool owns(std::size_t job) const { return static_cast<int>(job % count) == index - 1; }
};

struct RunOptions {
  int threads = 1;
  bool quiet = false;
  Shard shard;
  const std::atomic<bool>* cancel = nullptr;
  /// A stored ground truth of the scene (`--truth FILE`, checked with
  /// check_stored_truth) used instead of computing it; null: compute it.
  const ccd::TruthFile* truth = nullptr;
  std::string truth_file;  ///< where `truth` came from (recorded in the results)
  /// Told the jobs done and their total as they finish (Progress::Observer); empty: nobody.
  Progress::Observer progress;
};

/// The experiment's scene (file or generator). Throws ccd::InputError naming `file`.
ccd::Scene load_experiment_scene(const Experiment& e, const std::string& file);
/// Checks that the methods of `e` can run on `scene` (load_experiment_scene does; for a
/// scene given otherwise, e.g. in memory). Throws ccd::InputError naming `file`.
void check_experiment_scene(const Experiment& e, const ccd::Scene& scene, const std::string& file);

/// Checks that `truth` (read from `file`) is the ground truth of `scene`: a version 2
/// file's scene digest must equal the scene's (ccd/scene/scene_digest.hpp); any version's
/// horizon must equal the scene's and its body indices must exist. Throws ccd::InputError
/// naming `file` and the field otherwise. Returns false when the file is version 1 (no
/// digest: only the horizon and the indices could be checked).
bool check_stored_truth(const ccd::TruthFile& truth, const ccd::Scene& scene, const std::string& file);

/// Runs the experiment. Returns a null JSON value if cancelled.
nlohmann::json run_experiment(const Experiment& e, const ccd::Scene& scene, const RunOptions& options);

}  // namespace ccdlab
