#include "prepare_run.hpp"

#include "work_estimate.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>

#include <cstdio>
#include <utility>

namespace ccdlab {
namespace {

void set(std::string* doing, std::string what) {
  if (doing) *doing = std::move(what);
}

// The run's body-steps, refused past the limit unless forced.
void check_body_steps(const PreparedRun& run, bool force) {
  const Experiment& e = run.experiment;
  if (run.work <= kMaxWorkWithoutForce || force) return;
  throw ccd::InputError(run.file, "dt",
                        "the run needs " + work_number(run.work) + " body-steps (" +
                            std::to_string(run.scene.bodies.size()) + " bodies, up to " +
                            work_number(run.most_steps) +
                            " steps per job at dt = " + work_number(e.dt.back()) + "), above the limit " +
                            work_number(kMaxWorkWithoutForce) + " without --force");
}

// Shaped bodies: the certified truth (unless stored) and the rigid narrow phase, which
// tests at most a window's candidate pairs per step; refused past the limit unless forced.
double checked_pair_work(const PreparedRun& run, bool force) {
  const Experiment& e = run.experiment;
  if (!run.scene.has_non_spheres()) return 0.0;
  try {
    const ccd::Trajectories traj(run.scene);
    const double steps = experiment_work(e, 1, run.scene.horizon, run.shard.index, run.shard.count);
    const double work = run_pair_work(ccd::RigidMotion(run.scene, traj), steps, !run.truth_file.empty());
    check_work({work, kMaxPairWorkWithoutForce, "certified pair tests",
                std::to_string(run.scene.bodies.size()) + " bodies with shapes, " + work_number(steps) +
                    " steps in all; " + kPairWorkDetail},
               force, run.file, "scene");
    return work;
  } catch (const ccd::TooManyPieces&) {
    return 0.0;  // reported by the run itself, naming the body
  }
}

}  // namespace

PreparedRun prepare_run(Experiment e, const std::string& file, const RunRequest& request,
                        std::string* doing) {
  PreparedRun run;
  run.file = file;
  run.shard = request.shard;
  run.truth_file = request.truth_file;
  if (request.list_missed) e.list_missed = true;
  if (request.scene) {
    run.scene = *request.scene;
    check_experiment_scene(e, run.scene, file);
  } else {
    set(doing, e.scene_path.empty() ? "generating the scene " + e.scene_generator.dump()
                                    : "reading the scene " + e.scene_path);
    run.scene = load_experiment_scene(e, file);
  }
  check_dt_against_horizon(e, run.scene.horizon, file);
  if (!run.truth_file.empty()) {
    set(doing, "reading " + run.truth_file);
    run.stored_truth = ccd::load_truth(run.truth_file);
    run.truth_has_digest = check_stored_truth(run.stored_truth, run.scene, run.truth_file);
  }
  run.experiment = std::move(e);
  // The work, before any of it.
  run.work = experiment_work(run.experiment, run.scene.bodies.size(), run.scene.horizon, run.shard.index,
                             run.shard.count);
  run.most_steps = steps_per_job(run.scene.horizon, run.experiment.dt.back());
  check_body_steps(run, request.force);
  run.pair_work = checked_pair_work(run, request.force);
  return run;
}

PreparedRun prepare_run(const std::string& file, const RunRequest& request, std::string* doing) {
  set(doing, "reading " + file);
  return prepare_run(load_experiment(file), file, request, doing);
}

nlohmann::json run_prepared(const PreparedRun& run, RunOptions options) {
  options.shard = run.shard;
  if (!run.truth_file.empty()) {
    options.truth = &run.stored_truth;
    options.truth_file = run.truth_file;
  }
  const Experiment& e = run.experiment;
  try {
    return run_experiment(e, run.scene, options);
  } catch (const ccd::TooManyPieces& err) {
    throw ccd::InputError(
        e.scene_path.empty() ? run.file : e.scene_path,
        (e.scene_path.empty() ? "scene: bodies[" : "bodies[") + std::to_string(err.body()) + "]",
        "needs more than " + std::to_string(err.limit()) +
            " trajectory pieces over the horizon (wall reflections and acceleration changes; "
            "a body bouncing ever faster or too fast for its box)");
  }
}

}  // namespace ccdlab
