#pragma once
// One preparation of a sphere or rigid-body run for every front end (`ccdlab run`,
// Python's ccdlab.run): the experiment loaded, its scene, the timesteps checked against
// the horizon, a stored ground truth read and checked against the scene (`--truth FILE`),
// the work estimated and refused past its limits unless forced; then the run, with a
// body that needs too many trajectory pieces reported as bad input naming it.
#include "experiment.hpp"
#include "run_experiment.hpp"

#include <ccd/scene/scene.hpp>
#include <ccd/truth/truth_io.hpp>

#include <nlohmann/json.hpp>
#include <string>

namespace ccdlab {

/// What a front end asks of a run besides the experiment.
struct RunRequest {
  std::string truth_file;  ///< a stored ground truth to reuse ("" = compute it)
  bool force = false;      ///< run past the work limits
  bool list_missed = false;
  Shard shard;
  /// A scene given in memory (Python's ccdlab.run), run instead of the experiment's scene
  /// field (which then only names it in the results); null: the experiment's.
  const ccd::Scene* scene = nullptr;
};

/// A run ready to start: everything checked, nothing computed yet.
struct PreparedRun {
  Experiment experiment;
  std::string file;  ///< the experiment's file (named in every error)
  ccd::Scene scene;
  std::string truth_file;       ///< as requested
  ccd::TruthFile stored_truth;  ///< read from truth_file when one was given
  bool truth_has_digest =
      false;  ///< false for a ccdlab-truth/1 file: only its horizon and indices were checked
  Shard shard;
  double work = 0.0;        ///< body-steps of the run (its shard's jobs)
  double most_steps = 0.0;  ///< steps of the job with the smallest dt
  double pair_work = 0.0;   ///< certified pair tests (shaped bodies; 0 for spheres)
};

/// Prepares the run of `e` (read from `file`, or built from JSON and named by it): its
/// scene, the dt check, the stored truth, the work limits. Throws ccd::InputError naming
/// the file and the field. `doing`, when given, is kept up to date with what is being done
/// ("reading the scene scene.json"), for the one line a front end prints when memory runs out.
PreparedRun prepare_run(Experiment e, const std::string& file, const RunRequest& request,
                        std::string* doing = nullptr);

/// The same, reading the experiment from `file` first.
PreparedRun prepare_run(const std::string& file, const RunRequest& request, std::string* doing = nullptr);

/// Runs a prepared run with `options` (threads, quiet, cancel; the stored truth and the
/// shard come from `run`). Returns the ccdlab-results/2 document, or a null value when
/// cancelled. A body needing more trajectory pieces than the limit is a ccd::InputError
/// naming it.
nlohmann::json run_prepared(const PreparedRun& run, RunOptions options);

}  // namespace ccdlab
