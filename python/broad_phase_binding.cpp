// ccdlab.BroadPhase: any broad phase of the registry over an (n, 2, 3) numpy array of
// boxes (lo, hi per body; (n, 6) is accepted too), read in place as ccd::Aabb, returning
// the overlapping pairs as an (m, 2) uint32 array that owns the broad phase's own output
// (no copy). The GIL is released while it runs; one object serves one call at a time.
#include "bindings.hpp"

#include <ccd/broad_phase/registry.hpp>
#include <ccd/io/input_error.hpp>

#include <cmath>
#include <span>
#include <stdexcept>
#include <type_traits>

namespace ccdlab::python {

static_assert(sizeof(ccd::Aabb) == 6 * sizeof(double) && std::is_standard_layout_v<ccd::Aabb>,
              "boxes are read in place from (n, 2, 3) float64 arrays");
static_assert(sizeof(ccd::BodyPair) == 2 * sizeof(std::uint32_t),
              "pairs are returned in place as (m, 2) uint32");

using Boxes = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::span<const ccd::Aabb> boxes_view(const Boxes& boxes, const std::string& who) {
  const bool shape_ok = (boxes.ndim() == 3 && boxes.shape(1) == 2 && boxes.shape(2) == 3) ||
                        (boxes.ndim() == 2 && boxes.shape(1) == 6);
  if (!shape_ok)
    throw ccd::InputError(who, "boxes", "must be an (n, 2, 3) or (n, 6) array of lo, hi corners");
  const auto n = static_cast<std::size_t>(boxes.shape(0));
  const auto* data = reinterpret_cast<const ccd::Aabb*>(boxes.data());
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      const double lo = data[i].lo[c], hi = data[i].hi[c];
      if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi)
        throw ccd::InputError(who, "boxes[" + std::to_string(i) + "]",
                              "must be finite with lo <= hi on every axis (axis " + std::to_string(c) + ")");
    }
  return {data, n};
}

namespace {

class PyBroadPhase {
 public:
  explicit PyBroadPhase(const std::string& spec) : name_(spec) {
    try {
      spec_ = ccd::parse_broad_phase(spec);
    } catch (const std::invalid_argument& err) {
      throw ccd::InputError("ccdlab.BroadPhase", "spec", err.what());
    }
    broad_ = spec_.make();
  }

  py::array_t<std::uint32_t> find_pairs(const Boxes& boxes) {
    const std::span<const ccd::Aabb> view = boxes_view(boxes, "BroadPhase(" + name_ + ").find_pairs");
    std::vector<ccd::BodyPair> pairs;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      broad_->find_pairs(view, pairs);
    }
    const auto m = static_cast<py::ssize_t>(pairs.size());
    auto* heap = new std::vector<ccd::BodyPair>(std::move(pairs));
    py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<ccd::BodyPair>*>(p); });
    return py::array_t<std::uint32_t>({m, py::ssize_t{2}},
                                      reinterpret_cast<const std::uint32_t*>(heap->data()), owner);
  }

  py::dict stats() const {
    std::lock_guard lock(mutex_);
    py::dict d;
    d["box_tests"] = broad_->stats().box_tests;
    d["rebuilt"] = broad_->stats().rebuilt;
    for (const ccd::Counter& c : broad_->counters()) d[py::str(std::string(c.name))] = c.value;
    return d;
  }

  const std::string& name() const { return name_; }
  py::object options() const { return to_python(spec_.options.to_json()); }

 private:
  std::string name_;
  ccd::BroadPhaseSpec spec_;
  std::unique_ptr<ccd::BroadPhase> broad_;
  mutable std::mutex mutex_;
};

}  // namespace

void bind_broad_phases(py::module_& m) {
  py::class_<PyBroadPhase>(
      m, "BroadPhase",
      "A broad phase of the registry, e.g. BroadPhase('sap') or BroadPhase('grid:cell=2'); "
      "it keeps its state between calls (frames), as sap does")
      .def(py::init<const std::string&>(), py::arg("spec"))
      .def("find_pairs", &PyBroadPhase::find_pairs, py::arg("boxes"),
           "Every pair of overlapping boxes (closed intervals), a < b, each once: an (m, 2) uint32 array")
      .def("stats", &PyBroadPhase::stats,
           "Box tests, rebuilt, and the method's own counters of the last call")
      .def_property_readonly("name", &PyBroadPhase::name)
      .def_property_readonly("options", &PyBroadPhase::options)
      .def("__repr__", [](const PyBroadPhase& b) {
        return "<ccdlab.BroadPhase " + b.name() + ", options " + py::str(b.options()).cast<std::string>() + ">";
      });
}

}  // namespace ccdlab::python
