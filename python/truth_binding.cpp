// ccdlab.truth(scene) and ccdlab.load_truth(path): the exact contact intervals as numpy
// arrays. The arrays a, b, enter, exit are strided views of one event table (no copy);
// enter_error, exit_error and grazing exist when the truth has error fields (else None).
#include "bindings.hpp"
#include "interruptible.hpp"

#include <ccd/scene/scene_digest.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/truth_io.hpp>

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
  py::object enter_error = py::none(), exit_error = py::none(), grazing = py::none();
};

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
  if (!t.file->errors.empty()) {
    std::vector<double> enter_error, exit_error;
    std::vector<bool> grazing;
    for (const ccd::EventError& e : t.file->errors) {
      enter_error.push_back(e.enter_error);
      exit_error.push_back(e.exit_error);
      grazing.push_back(e.grazing);
    }
    t.enter_error = owning_array(std::move(enter_error), {n});
    t.exit_error = owning_array(std::move(exit_error), {n});
    py::array_t<bool> g(n);
    for (py::ssize_t i = 0; i < n; ++i) g.mutable_at(i) = grazing[static_cast<std::size_t>(i)];
    t.grazing = g;
  }
  return t;
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
      .def_property_readonly("horizon", [](const PyTruth& t) { return t.file->horizon; })
      .def_property_readonly("scene_sha256", [](const PyTruth& t) { return t.file->scene_sha256; })
      .def("__len__", [](const PyTruth& t) { return t.file->events.size(); })
      .def("__iter__", [](const PyTruth& t) { return py::iter(py::make_tuple(t.a, t.b, t.enter, t.exit)); })
      .def(
          "to_json", [](const PyTruth& t) { return to_python(ccd::truth_to_json(*t.file)); },
          "The ccdlab-truth/2 document, as `ccdlab truth` writes it")
      .def(
          "save", [](const PyTruth& t, const std::string& path) { ccd::save_truth(*t.file, path); },
          py::arg("path"));

  m.def(
      "truth",
      [](const PyScene& scene, unsigned threads) {
        ccd::TruthFile file = run_interruptible([&]() {
          ccd::TruthOptions options;
          options.threads = threads;
          ccd::TruthFile f;
          f.horizon = scene.scene().horizon;
          f.events = ccd::compute_truth(*scene.trajectories(), options);
          f.scene_sha256 = ccd::scene_digest(scene.scene());
          return f;
        });
        return make_truth(std::move(file));
      },
      py::arg("scene"), py::arg("threads") = 0,
      "The exact ground truth of the scene (threads=0: every core); Ctrl-C waits for it to finish");
  m.def(
      "load_truth",
      [](const std::string& path) {
        return make_truth(run_interruptible([&]() { return ccd::load_truth(path); }));
      },
      py::arg("path"), "Reads and validates a ccdlab-truth file");
}

}  // namespace ccdlab::python
