#include "run_experiment.hpp"

#include "environment.hpp"
#include "job_order.hpp"
#include "../generators/registry.hpp"
#include "method.hpp"
#include "progress.hpp"
#include "runner.hpp"

#include <ccd/io/utf8_text.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/util/parallel_for.hpp>
#include <ccd/util/parameters.hpp>
#include <ccd/truth/truth.hpp>
#include <ccd/truth/truth_io.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

namespace ccdlab {

using nlohmann::json;

namespace {

ccd::Scene read_experiment_scene(const Experiment& e, const std::string& file) {
  if (!e.scene_path.empty()) return ccd::load_scene(e.scene_path);
  json params = e.scene_generator;
  const std::string name = params["generator"].get<std::string>();
  params.erase("generator");
  try {
    return generate_scene(name, params);
  } catch (const std::invalid_argument& err) {
    throw ccd::InputError(file, "scene", err.what());
  }
}

}  // namespace

ccd::Scene load_experiment_scene(const Experiment& e, const std::string& file) {
  ccd::Scene scene = read_experiment_scene(e, file);
  check_experiment_scene(e, scene, file);
  return scene;
}

void check_experiment_scene(const Experiment& e, const ccd::Scene& scene, const std::string& file) {
  // The earliest-contact scheduler's images (pipeline/scheduler_images.hpp) carry
  // sphere paths only: in a wrapped scene it refuses shaped bodies.
  if (scene.wraps() && scene.has_non_spheres())
    for (std::size_t i = 0; i < e.methods.size(); ++i)
      if (e.methods[i].scheduled())
        throw ccd::InputError(file, "methods[" + std::to_string(i) + "]",
                              "@earliest takes plain spheres only in a scene that wraps around (box.boundary "
                              "\"wrap\"); use the fixed-step method " + e.methods[i].fixed_step_name());
}

namespace {

json scene_summary(const Experiment& e, const ccd::Scene& s, const ccd::Trajectories& traj) {
  double rmin = 0, rmax = 0;
  if (!s.bodies.empty()) {
    rmin = rmax = s.bodies[0].radius;
    for (const ccd::Body& b : s.bodies) {
      rmin = std::min(rmin, b.radius);
      rmax = std::max(rmax, b.radius);
    }
  }
  json j = {{"source", e.scene_path.empty() ? json(e.scene_generator) : json(ccd::escape_invalid_utf8(e.scene_path))},
            {"bodies", s.bodies.size()},
            {"horizon", s.horizon},
            {"motion", ccd::to_string(s.motion_kind())},
            {"gravity", {s.gravity.x(), s.gravity.y(), s.gravity.z()}},
            {"radius_min", rmin},
            {"radius_max", rmax},
            {"max_acceleration", s.max_acceleration()},
            {"trajectory_pieces", traj.total_pieces()}};
  if (s.box)
    j["box"] = {{"min", {s.box->min.x(), s.box->min.y(), s.box->min.z()}},
                {"max", {s.box->max.x(), s.box->max.y(), s.box->max.z()}}};
  return j;
}

std::string job_label(const std::string& method, double dt) {
  std::ostringstream os;
  os << method << " dt=" << dt;
  return os.str();
}

}  // namespace

bool check_stored_truth(const ccd::TruthFile& truth, const ccd::Scene& scene, const std::string& file) {
  if (truth.version >= 2) {
    const std::string digest = ccd::scene_digest(scene);
    if (truth.scene_sha256 != digest)
      throw ccd::InputError(file, "scene_sha256",
                            "this is the ground truth of another scene (" + truth.scene_sha256.substr(0, 12) +
                                "..., the experiment's scene is " + digest.substr(0, 12) +
                                "...); compute it with `ccdlab truth SCENE.json -o FILE`");
  }
  if (truth.horizon != scene.horizon)
    throw ccd::InputError(file, "horizon",
                          "is " + ccd::format_number(truth.horizon) + ", the experiment's scene runs to " +
                              ccd::format_number(scene.horizon));
  for (std::size_t i = 0; i < truth.events.size(); ++i)
    if (truth.events[i].b >= scene.bodies.size())
      throw ccd::InputError(file, "events[" + std::to_string(i) + "].b",
                            "body " + std::to_string(truth.events[i].b) + " does not exist (the scene has " +
                                std::to_string(scene.bodies.size()) + " bodies)");
  for (std::size_t i = 0; i < truth.static_events.size(); ++i) {
    const ccd::StaticEvent& s = truth.static_events[i];
    const std::string at = "static_events[" + std::to_string(i) + "]";
    if (s.body >= scene.bodies.size())
      throw ccd::InputError(file, at + ".body",
                            "body " + std::to_string(s.body) + " does not exist (the scene has " +
                                std::to_string(scene.bodies.size()) + " bodies)");
    if (s.polygon >= scene.scenery.size())
      throw ccd::InputError(file, at + ".polygon",
                            "polygon " + std::to_string(s.polygon) + " does not exist (the scene has " +
                                std::to_string(scene.scenery.size()) + " polygons)");
  }
  return truth.version >= 2;
}

json run_experiment(const Experiment& e, const ccd::Scene& scene, const RunOptions& options) {
  struct Job {
    std::size_t index;
    MethodSpec method;
    double dt;
    double hz;
  };
  std::vector<Job> jobs;
  const std::size_t total_jobs = e.methods.size() * e.dt.size();
  for (std::size_t m = 0; m < e.methods.size(); ++m)
    for (std::size_t d = 0; d < e.dt.size(); ++d) {
      const std::size_t index = m * e.dt.size() + d;
      if (options.shard.owns(index)) jobs.push_back({index, e.methods[m], e.dt[d], e.hz[d]});
    }

  Progress progress(jobs.size(), options.quiet, options.progress);
  progress.phase("scene: " + std::to_string(scene.bodies.size()) + " bodies, horizon " +
                 std::to_string(scene.horizon) + " s; " +
                 (options.truth ? "ground truth from " + options.truth_file : std::string("computing exact ground truth")));
  const auto t0 = std::chrono::steady_clock::now();
  const ccd::Trajectories traj(scene);
  ccd::TruthOptions topts;
  topts.threads = static_cast<unsigned>(std::max(0, options.threads));
  topts.cancel = options.cancel;
  topts.progress = [&progress](std::size_t done, std::size_t total) {
    progress.advance("candidate pairs solved", done, total);
  };
  // The scene's motion: the truth and every method take it.
  const ccd::RigidMotion motion(scene, traj);
  // The stored truth (its static events too, when it has them), else one computed truth.
  ccd::Truth computed;
  const bool stored_complete = options.truth && (scene.scenery.empty() || options.truth->has_scenery);
  if (!stored_complete) {
    computed = ccd::compute_truth(motion, scene.scenery, topts);
    if (computed.stats.cancelled) return json();
  }
  const ccd::Truth& body_truth = options.truth ? *options.truth : computed;
  const ccd::Truth& static_truth = stored_complete ? *options.truth : computed;
  // Certified events (rigid bodies) widen the matching window by their largest error.
  const double truth_error = std::max(ccd::largest_error(body_truth.errors), ccd::largest_error(static_truth.static_errors));
  const TruthIndex truth(std::vector<ccd::ContactEvent>(body_truth.events));
  const std::vector<ccd::StaticEvent>& static_events = static_truth.static_events;
  const double truth_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::size_t tangent = 0;
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const ccd::ContactEvent& ev : truth.events()) {
    tangent += ev.enter == ev.exit;
    pairs.insert({ev.a, ev.b});
  }
  progress.phase("ground truth: " + std::to_string(truth.events().size()) + " events in " +
                 std::to_string(truth_seconds) + " s; running " + std::to_string(jobs.size()) + " jobs");

  RunInput in;
  in.scene = &scene;
  in.motion = &motion;
  in.truth = &truth;
  in.truth_error = truth_error;
  in.errors = body_truth.errors;
  in.static_errors = static_truth.static_errors;
  in.static_events = static_events;
  in.acceleration_bound = e.acceleration_bound >= 0.0 ? e.acceleration_bound : scene.max_acceleration();
  in.repeats = e.repeats;
  in.cancel = options.cancel;
  in.list_missed = e.list_missed;

  std::vector<RunRecord> records(jobs.size());
  // Costliest (smallest dt) first; records[i] stays job i's (experiments/job_order.hpp).
  std::vector<double> job_dt;
  for (const Job& j : jobs) job_dt.push_back(j.dt);
  const std::vector<std::size_t> order = job_order(job_dt);
  progress.start_jobs();
  ccd::parallel_for(jobs.size(), static_cast<unsigned>(std::max(1, options.threads)), [&](std::size_t k, unsigned) {
    const std::size_t i = order[k];
    if (options.cancel && options.cancel->load()) {
      records[i].cancelled = true;
      return;
    }
    records[i] = run_method(in, jobs[i].method, jobs[i].dt);
    records[i].hz = jobs[i].hz;
    progress.done(job_label(jobs[i].method.name, jobs[i].dt));
  });
  progress.finish();
  if (options.cancel && options.cancel->load()) return json();
  for (const RunRecord& r : records)
    if (r.cancelled) return json();

  json out;
  out["format"] = "ccdlab-results/2";
  out["experiment"] = experiment_to_json(e);
  out["experiment"]["acceleration_bound_used"] = in.acceleration_bound;
  out["scene"] = scene_summary(e, scene, traj);
  out["truth"] = {{"events", truth.events().size()},
                  {"tangent_events", tangent},
                  {"pairs", pairs.size()},
                  {"seconds", truth_seconds},
                  {"source", options.truth ? options.truth_file : std::string("computed")},
                  {"scene_sha256", ccd::scene_digest(scene)}};
  if (!scene.scenery.empty()) out["truth"]["static_events"] = static_events.size();
  // Events the truth could not decide: counted apart in every record (`undecided`).
  const auto undecided = [](const std::vector<ccd::EventError>& errors) {
    return static_cast<std::size_t>(std::count_if(errors.begin(), errors.end(), [](const ccd::EventError& x) { return x.undecided; }));
  };
  if (const std::size_t u = undecided(body_truth.errors)) out["truth"]["undecided_events"] = u;
  if (const std::size_t u = undecided(static_truth.static_errors); u && !scene.scenery.empty())
    out["truth"]["static_undecided_events"] = u;
  out["environment"] = environment_json(options.threads);
  out["shard"] = {{"index", options.shard.index}, {"count", options.shard.count}, {"jobs", total_jobs}};
  json recs = json::array();
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    json r = to_json(records[i], e.list_missed);
    r["job"] = jobs[i].index;
    recs.push_back(std::move(r));
  }
  out["records"] = std::move(recs);
  out["peak_memory_bytes"] = peak_memory_bytes();
  return out;
}

}  // namespace ccdlab
