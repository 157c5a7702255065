// ccdlab.run(experiment) and ccdlab.methods(): the same calls as `ccdlab run` and
// `ccdlab methods`. run returns the ccdlab-results/2 document as a dict; Ctrl-C cancels the
// jobs at their next step and raises KeyboardInterrupt.
#include "bindings.hpp"
#include "interruptible.hpp"

#include <experiments/experiment.hpp>
#include <experiments/method.hpp>
#include <experiments/prepare_run.hpp>
#include <experiments/run_experiment.hpp>

#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/truth_io.hpp>
#include <ccd/util/parallel_for.hpp>

#include <atomic>
#include <memory>
#include <optional>
#include <utility>

namespace ccdlab::python {
namespace {

// The file name that in-memory scenes go by in the results (experiment.scene, scene.source).
constexpr const char* kInMemoryScene = "<in memory>";

/// The scene of an experiment dict when it is given in memory: a ccdlab.Scene, or a
/// ccdlab-scene document as a dict (a dict with "generator" is a generator spec, left to
/// the experiment). The dict's scene field is then replaced by kInMemoryScene.
std::shared_ptr<const ccd::Scene> in_memory_scene(py::dict& experiment) {
  if (!experiment.contains("scene")) return nullptr;
  const py::object scene = experiment["scene"];
  std::shared_ptr<const ccd::Scene> out;
  if (py::isinstance<PyScene>(scene)) {
    out = std::make_shared<const ccd::Scene>(scene.cast<const PyScene&>().scene());
  } else if (py::isinstance<py::dict>(scene) && !scene.cast<py::dict>().contains("generator")) {
    const std::string file = "experiment";
    try {
      out = std::make_shared<const ccd::Scene>(ccd::scene_from_json(from_python(scene, file), file));
    } catch (const ccd::InputError& err) {
      // "experiment: bodies[3].radius: ..." -> "experiment: scene.bodies[3].radius: ..."
      const std::string prefix = err.file() + ": " + (err.field().empty() ? "" : err.field() + ": ");
      const std::string what = std::string(err.what()).substr(prefix.size());
      throw ccd::InputError(file, err.field().empty() ? "scene" : "scene." + err.field(), what);
    }
  } else {
    return nullptr;
  }
  experiment = experiment.attr("copy")();  // a copy: the caller's dict keeps its scene
  experiment["scene"] = kInMemoryScene;
  return out;
}

py::object run(const py::object& experiment, unsigned threads, std::optional<std::string> truth_path,
               bool quiet, bool force, bool missed_events, const py::object& progress) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw ccd::InputError("ccdlab.run", "progress", "must be callable as progress(done, total), or None");
  const bool is_path = py::isinstance<py::str>(experiment) || py::hasattr(experiment, "__fspath__");
  std::string file = "experiment";
  RunRequest request;  // as `ccdlab run` asks: one preparation (experiments/prepare_run.hpp)
  request.truth_file = truth_path.value_or(std::string());
  request.force = force;
  request.list_missed = missed_events;  // as `ccdlab run --list-missed`
  std::optional<Experiment> given;
  std::shared_ptr<const ccd::Scene> scene;
  if (is_path) {
    file = py::str(py::module_::import("os").attr("fspath")(experiment)).cast<std::string>();
  } else {
    py::object doc = experiment;
    if (py::isinstance<py::dict>(experiment)) {
      py::dict d = experiment.cast<py::dict>();
      scene = in_memory_scene(d);
      doc = d;
    }
    given = experiment_from_json(from_python(doc, file), file);
    request.scene = scene.get();
  }
  std::atomic<bool> cancel{false};
  std::atomic<std::size_t> done{0}, total{0};
  std::atomic<bool> started{false};
  std::size_t reported = static_cast<std::size_t>(-1);
  const auto report = [&] {  // with the GIL, on the calling thread
    if (progress.is_none() || !started.load()) return;
    const std::size_t d = done.load(), n = total.load();
    if (d == reported) return;
    reported = d;
    progress(d, n);
  };
  nlohmann::json results = run_interruptible(
      [&]() {
        const PreparedRun prepared =
            given ? prepare_run(std::move(*given), file, request) : prepare_run(file, request);
        RunOptions options;
        options.threads = static_cast<int>(ccd::resolve_threads(threads));
        options.quiet = quiet;
        options.cancel = &cancel;
        if (!progress.is_none())
          options.progress = [&](std::size_t d, std::size_t n) {  // under the progress lock
            total.store(n);
            done.store(d);
            started.store(true);
          };
        return run_prepared(prepared, options);
      },
      &cancel, report);
  return to_python(results);
}

py::dict parameters(std::span<const ccd::ParameterSpec> specs) {
  py::dict out;
  for (const ccd::ParameterSpec& p : specs) {
    py::dict d;
    d["default"] = p.default_value;
    d["unit"] = std::string(p.unit);
    d["doc"] = std::string(p.doc);
    d["description"] = ccd::describe_parameter(p);
    out[py::str(std::string(p.name))] = d;
  }
  return out;
}

py::dict methods() {
  py::list bounds, broad;
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    py::dict d;
    d["name"] = std::string(b.name);
    d["description"] = std::string(b.description);
    d["knowledge"] = std::string(ccd::to_string(b.knowledge));
    d["conservative"] = b.conservative;
    d["parameters"] = parameters(b.parameters);
    bounds.append(d);
  }
  for (const ccd::BroadPhaseInfo& p : ccd::broad_phase_registry()) {
    py::dict d;
    d["name"] = std::string(p.name);
    d["description"] = std::string(p.description);
    d["parameters"] = parameters(p.parameters);
    broad.append(d);
  }
  py::list names;
  for (const std::string& n : all_method_names()) names.append(n);
  py::dict out;
  out["bounds"] = bounds;
  out["broad_phases"] = broad;
  out["methods"] = names;
  return out;
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("run", &run, py::arg("experiment"), py::kw_only(), py::arg("threads") = 0,
        py::arg("truth") = py::none(), py::arg("quiet") = true, py::arg("force") = false,
        py::arg("missed_events") = false, py::arg("progress") = py::none(),
        "Runs an experiment (a file path, or a ccdlab-experiment/1 dict whose scene is a path relative to "
        "the current folder, a generator spec, a ccdlab.Scene or a ccdlab-scene dict: the last two run in "
        "memory, named \"<in memory>\" in the results) and returns the ccdlab-results/2 document `ccdlab run` "
        "writes. threads=0: every core; truth: a truth file to reuse; missed_events=True lists in each "
        "record the events it missed ({a, b, enter, exit}, as `ccdlab run --list-missed`); "
        "progress(done, total): jobs (method x dt) finished, called on the calling thread at most every "
        "50 ms once the ground truth is known, and at the end (an exception in it stops the run)");
  m.def("methods", &methods,
        "The bounds and broad phases with their options, and every composed method name (`ccdlab methods`)");
}

}  // namespace ccdlab::python
