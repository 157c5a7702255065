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
#include <ccd/truth/truth_io.hpp>
#include <ccd/util/parallel_for.hpp>

#include <atomic>
#include <optional>
#include <utility>

namespace ccdlab::python {
namespace {

py::object run(const py::object& experiment, unsigned threads, std::optional<std::string> truth_path,
               bool quiet, bool force, bool missed_events) {
  const bool is_path = py::isinstance<py::str>(experiment) || py::hasattr(experiment, "__fspath__");
  std::string file = "experiment";
  RunRequest request;  // as `ccdlab run` asks: one preparation (experiments/prepare_run.hpp)
  request.truth_file = truth_path.value_or(std::string());
  request.force = force;
  request.list_missed = missed_events;  // as `ccdlab run --list-missed`
  std::optional<Experiment> given;
  if (is_path) file = py::str(py::module_::import("os").attr("fspath")(experiment)).cast<std::string>();
  else given = experiment_from_json(from_python(experiment, file), file);
  std::atomic<bool> cancel{false};
  nlohmann::json results = run_interruptible(
      [&]() {
        const PreparedRun prepared =
            given ? prepare_run(std::move(*given), file, request) : prepare_run(file, request);
        RunOptions options;
        options.threads = static_cast<int>(ccd::resolve_threads(threads));
        options.quiet = quiet;
        options.cancel = &cancel;
        return run_prepared(prepared, options);
      },
      &cancel);
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
        py::arg("missed_events") = false,
        "Runs an experiment (a file path, or a ccdlab-experiment/1 dict whose scene path is relative to "
        "the current folder) and returns the ccdlab-results/2 document `ccdlab run` writes. threads=0: every "
        "core; truth: a truth file to reuse; missed_events=True lists in each record the events it missed "
        "({a, b, enter, exit}, as `ccdlab run --list-missed`)");
  m.def("methods", &methods,
        "The bounds and broad phases with their options, and every composed method name (`ccdlab methods`)");
}

}  // namespace ccdlab::python
