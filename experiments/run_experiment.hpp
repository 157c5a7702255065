#pragma once
// Runs a whole experiment: loads or generates the scene, computes the ground truth once,
// runs every (method, dt) job on a pool of threads, and assembles a `ccdlab-results/1`
// document (docs/experiments.md). Counts do not depend on the thread count: every job is
// independent and results are stored by job index.
#include "experiment.hpp"

#include <ccd/scene/scene.hpp>

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
};

/// The experiment's scene (file or generator). Throws ccd::InputError naming `file`.
ccd::Scene load_experiment_scene(const Experiment& e, const std::string& file);

/// Runs the experiment. Returns a null JSON value if cancelled.
nlohmann::json run_experiment(const Experiment& e, const ccd::Scene& scene, const RunOptions& options);

}  // namespace ccdlab
