// ccdlab.truth(scene) and ccdlab.load_truth(path): the contact intervals as numpy arrays,
// for every kind of scene (ccd/truth/truth.hpp: the call `ccdlab truth` makes). The arrays
// a, b, enter, exit are strided views of one event table (no copy); enter_error,
// exit_error, grazing and undecided exist when the truth has error fields (else None); static_body,
// static_polygon, static_enter, static_exit (and static_enter_error, static_exit_error,
// static_grazing, static_undecided when certified) hold the body-scenery events of a scene with scenery.
#include "bindings.hpp"

#include <ccd/io/input_error.hpp>

#include <algorithm>
#include <sstream>
#include "interruptible.hpp"

#include <ccd/scene/scene_digest.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/truth/truth.hpp>
#include <ccd/truth/truth_io.hpp>

#include <atomic>
#include <cstddef>

namespace ccdlab::python {
namespace {

static_assert(sizeof(ccd::ContactEvent) == 24 && offsetof(ccd::ContactEvent, a) == 0 &&
                  offsetof(ccd::ContactEvent, b) == 4 && offsetof(ccd::ContactEvent, enter) == 8 &&
                  offsetof(ccd::ContactEvent, exit) == 16,
              "the numpy views of the truth assume this layout");

struct PyTruth {
  std::shared_ptr<ccd::TruthFile> file;
  py::object owner;  ///< keeps `file` alive for the views
  py::array a, b, enter, exit;
  py::object enter_error = py::none(), exit_error = py::none(), grazing = py::none(), undecided = py::none();
  /// Body-scenery events (None without scenery): body, polygon (uint32), enter, exit (s),
  /// and their error fields (None when every static event is exact).
  py::object static_body = py::none(), static_polygon = py::none(), static_enter = py::none(),
             static_exit = py::none();
  py::object static_enter_error = py::none(), static_exit_error = py::none(), static_grazing = py::none(),
             static_undecided = py::none();
};

// The error fields of `errors` as arrays (enter_error, exit_error, grazing, undecided).
void error_arrays(const std::vector<ccd::EventError>& errors, py::object& enter_error, py::object& exit_error,
                  py::object& grazing, py::object& undecided) {
  const auto n = static_cast<py::ssize_t>(errors.size());
  std::vector<double> enter, exit;
  py::array_t<bool> g(n), u(n);
  for (std::size_t i = 0; i < errors.size(); ++i) {
    enter.push_back(errors[i].enter_error);
    exit.push_back(errors[i].exit_error);
    g.mutable_at(static_cast<py::ssize_t>(i)) = errors[i].grazing;
    u.mutable_at(static_cast<py::ssize_t>(i)) = errors[i].undecided;
  }
  enter_error = owning_array(std::move(enter), {n});
  exit_error = owning_array(std::move(exit), {n});
  grazing = g;
  undecided = u;
}

void static_arrays(const ccd::Truth& truth, PyTruth& t) {
  if (!truth.has_scenery) return;
  const auto n = static_cast<py::ssize_t>(truth.static_events.size());
  std::vector<std::uint32_t> body, polygon;
  std::vector<double> enter, exit;
  for (const ccd::StaticEvent& e : truth.static_events) {
    body.push_back(e.body);
    polygon.push_back(e.polygon);
    enter.push_back(e.enter);
    exit.push_back(e.exit);
  }
  t.static_body = owning_array(std::move(body), {n});
  t.static_polygon = owning_array(std::move(polygon), {n});
  t.static_enter = owning_array(std::move(enter), {n});
  t.static_exit = owning_array(std::move(exit), {n});
  if (!truth.static_errors.empty()) error_arrays(truth.static_errors, t.static_enter_error, t.static_exit_error, t.static_grazing,
                 t.static_undecided);
}

PyTruth make_truth(ccd::TruthFile truth) {
  PyTruth t;
  t.file = std::make_shared<ccd::TruthFile>(std::move(truth));
  auto* keep = new std::shared_ptr<ccd::TruthFile>(t.file);
  t.owner = py::capsule(keep, [](void* p) { delete static_cast<std::shared_ptr<ccd::TruthFile>*>(p); });
  const auto n = static_cast<py::ssize_t>(t.file->events.size());
  const py::ssize_t stride = sizeof(ccd::ContactEvent);
  auto* base = reinterpret_cast<char*>(t.file->events.data());
  t.a = py::array(py::dtype::of<std::uint32_t>(), {n}, {stride}, base + offsetof(ccd::ContactEvent, a),
                  t.owner);
  t.b = py::array(py::dtype::of<std::uint32_t>(), {n}, {stride}, base + offsetof(ccd::ContactEvent, b),
                  t.owner);
  t.enter =
      py::array(py::dtype::of<double>(), {n}, {stride}, base + offsetof(ccd::ContactEvent, enter), t.owner);
  t.exit =
      py::array(py::dtype::of<double>(), {n}, {stride}, base + offsetof(ccd::ContactEvent, exit), t.owner);
  for (py::array* view : {&t.a, &t.b, &t.enter, &t.exit})  // read-only views of the table
    view->attr("flags").attr("writeable") = false;
  if (!t.file->errors.empty()) error_arrays(t.file->errors, t.enter_error, t.exit_error, t.grazing, t.undecided);
  static_arrays(*t.file, t);
  return t;
}

/// "<ccdlab.Truth 9 events (2 grazing, 1 undecided), 3 static events, horizon 2 s>".
std::string truth_repr(const ccd::Truth& t) {
  const auto count = [](const std::vector<ccd::EventError>& errors, bool ccd::EventError::*flag) {
    return std::count_if(errors.begin(), errors.end(), [&](const ccd::EventError& e) { return e.*flag; });
  };
  std::ostringstream out;
  out << "<ccdlab.Truth " << t.events.size() << " events";
  if (!t.errors.empty())
    out << " (" << count(t.errors, &ccd::EventError::grazing) << " grazing, "
        << count(t.errors, &ccd::EventError::undecided) << " undecided)";
  out << ", " << t.static_events.size() << " static events, horizon " << t.horizon << " s>";
  return out.str();
}

}  // namespace

void bind_truth(py::module_& m) {
  py::class_<PyTruth>(m, "Truth",
                      "Exact contact intervals, sorted by (enter, a, b): a, b (uint32), enter, exit (s); "
                      "`a, b, enter, exit = truth` unpacks them")
      .def_readonly("a", &PyTruth::a)
      .def_readonly("b", &PyTruth::b)
      .def_readonly("enter", &PyTruth::enter)
      .def_readonly("exit", &PyTruth::exit)
      .def_readonly("enter_error", &PyTruth::enter_error)
      .def_readonly("exit_error", &PyTruth::exit_error)
      .def_readonly("grazing", &PyTruth::grazing)
      .def_readonly("undecided", &PyTruth::undecided)
      .def_readonly("static_body", &PyTruth::static_body)
      .def_readonly("static_polygon", &PyTruth::static_polygon)
      .def_readonly("static_enter", &PyTruth::static_enter)
      .def_readonly("static_exit", &PyTruth::static_exit)
      .def_readonly("static_enter_error", &PyTruth::static_enter_error)
      .def_readonly("static_exit_error", &PyTruth::static_exit_error)
      .def_readonly("static_grazing", &PyTruth::static_grazing)
      .def_readonly("static_undecided", &PyTruth::static_undecided)
      .def_property_readonly("horizon", [](const PyTruth& t) { return t.file->horizon; })
      .def_property_readonly("scene_sha256", [](const PyTruth& t) { return t.file->scene_sha256; })
      .def("__len__", [](const PyTruth& t) { return t.file->events.size(); })
      .def("__repr__", [](const PyTruth& t) { return truth_repr(*t.file); })
      .def("__iter__", [](const PyTruth& t) { return py::iter(py::make_tuple(t.a, t.b, t.enter, t.exit)); })
      .def(
          "to_json", [](const PyTruth& t) { return to_python(ccd::truth_to_json(*t.file)); },
          "The ccdlab-truth/2 document, as `ccdlab truth` writes it")
      .def(
          "save", [](const PyTruth& t, const std::string& path) { ccd::save_truth(*t.file, path); },
          py::arg("path"));

  m.def(
      "truth",
      [](const PyScene& scene, unsigned threads, const py::object& progress) {
        if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
          throw ccd::InputError("ccdlab.truth", "progress", "must be callable as progress(done, total), or None");
        std::atomic<bool> cancel{false};
        std::atomic<std::size_t> done{0}, total{0};
        std::size_t reported = static_cast<std::size_t>(-1);
        const auto report = [&] {  // with the GIL, on the calling thread
          const std::size_t d = done.load(), n = total.load();
          if (progress.is_none() || n == 0 || d == reported) return;
          reported = d;
          progress(d, n);
        };
        ccd::Truth truth = run_interruptible(
            [&]() {
              ccd::TruthOptions options;
              options.threads = threads;
              options.cancel = &cancel;
              if (!progress.is_none())
                options.progress = [&](std::size_t d, std::size_t n) {
                  total.store(n);
                  done.store(d);
                };
              ccd::Truth t = ccd::compute_truth(*scene.motion(), scene.scene().scenery, options);
              t.scene_sha256 = ccd::scene_digest(scene.scene());
              return t;
            },
            &cancel, report);
        return make_truth(std::move(truth));
      },
      py::arg("scene"), py::arg("threads") = 0, py::arg("progress") = py::none(),
      "The ground truth of the scene, as `ccdlab truth` computes it (threads=0: every core): exact for "
      "spheres, certified brackets with error fields for other shapes, static events with scenery; "
      "progress(done, total) is called on the calling thread as the work advances (units of the "
      "truth's own progress, as `ccdlab truth` prints it), at most every 50 ms; Ctrl-C, or an "
      "exception of progress, stops it");
  m.def(
      "load_truth",
      [](const std::string& path) {
        return make_truth(run_interruptible([&]() { return ccd::load_truth(path); }));
      },
      py::arg("path"), "Reads and validates a ccdlab-truth file");
}

}  // namespace ccdlab::python
