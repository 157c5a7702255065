#pragma once
// An experiment: one scene, a list of timesteps, a list of methods (`ccdlab-experiment/1`,
// documented in docs/experiments.md). Parsing fills in every default, so the results
// file records exactly what ran.
#include "method.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ccdlab {

struct Experiment {
  std::string name;                   ///< a plain file name (results/NAME.json), never a path
  /// Either a scene file path (resolved against the experiment file's folder) ...
  std::string scene_path;
  /// ... or a generator spec {"generator": NAME, params...} (scene_path empty).
  nlohmann::json scene_generator;
  std::vector<double> dt;             ///< sorted descending, unique, each in (0, horizon]
  std::vector<double> hz;             ///< parallel to dt: the frequency as given in "hz", else 1 / dt
  std::vector<bool> hz_given;         ///< parallel to dt: the timestep came from "hz"
  std::vector<MethodSpec> methods;    ///< BOUND/BROADPHASE[@SCHEDULER], parsed once (method.hpp)
  double acceleration_bound = -1.0;   ///< A for Bounded bounds; < 0: the scene's largest
  int repeats = 1;                    ///< timing repeats (counts must not change)
  bool list_missed = false;           ///< records list their missed events (missed_events)
  nlohmann::json source;              ///< the parsed file with defaults filled in
};

/// The experiment's name, a plain file name (results/NAME.json): the field "name" of `j`,
/// validated (throws ccd::InputError naming `file`), else the stem of `file` with anything
/// but letters, digits, '.', '_' and '-' made '_' (`fallback` when the stem is empty).
std::string experiment_name(const nlohmann::json& j, const std::string& file, const std::string& fallback);
/// Parses and validates an experiment (methods, dt > 0, repeats >= 1, no unknown field,
/// ...); throws
/// ccd::InputError naming `file` and the field. The dt <= horizon check needs the scene:
/// see check_dt_against_horizon.
Experiment experiment_from_json(const nlohmann::json& j, const std::string& file);
/// Reads an experiment file; a relative scene path is resolved against its folder.
Experiment load_experiment(const std::string& path);
/// Most steps one job may take: with horizon / dt <= 2^52 the sample times k dt are
/// distinct doubles and k is exact.
inline constexpr double kMaxStepsPerJob = 0x1p52;
/// Throws ccd::InputError if some dt exceeds the horizon or needs more than
/// kMaxStepsPerJob steps (a dt the horizon cannot resolve).
void check_dt_against_horizon(const Experiment& e, double horizon, const std::string& file);

/// The work `ccdlab run` accepts without --force, in body-steps (below).
inline constexpr double kMaxWorkWithoutForce = 1e11;
/// Steps of one job (at most; the runner's exact count differs by at most one).
double steps_per_job(double horizon, double dt);
/// The work of the jobs of shard K/N (1/1: every job): steps x bodies x repeats summed over
/// the jobs, in body-steps. At about 10-100 ns per body-step, 1e11 is
/// hours (the default experiment is 4.3e8).
double experiment_work(const Experiment& e, std::size_t bodies, double horizon, int shard_index = 1,
                       int shard_count = 1);
/// The JSON form with defaults filled in (what the results file records).
nlohmann::json experiment_to_json(const Experiment& e);

}  // namespace ccdlab
