// ccdlab.Bound: any bound of the registry. prepare(scene, t0, t1) evaluates every body's
// state at t0 and gives the bound the scene's motion (its shapes and spin too, which the
// orientation-aware bounds read), and returns the bound's boxes as an (n, 2, 3) array that owns the bound's own
// output (no copy), ready for BroadPhase.find_pairs; test_pairs(pairs) runs the bound's
// pair test on an (m, 2) array of pairs.
#include "bindings.hpp"

#include <bounds/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <ccd/io/input_error.hpp>

#include <stdexcept>

namespace ccdlab::python {
namespace {

class PyBound {
 public:
  explicit PyBound(const std::string& spec) : name_(spec) {
    try {
      spec_ = ccd::parse_bound(spec);
    } catch (const std::invalid_argument& err) {
      throw ccd::InputError("ccdlab.Bound", "spec", err.what());
    }
    bound_ = spec_.make();
  }

  py::array_t<double> prepare(const std::shared_ptr<PyScene>& scene, double t0, double t1,
                              std::optional<double> acceleration_bound) {
    const std::string who = "Bound(" + name_ + ").prepare";
    const double T = scene->scene().horizon;
    if (!(t0 >= 0.0 && t0 <= T)) throw ccd::InputError(who, "t0", "must be in [0, horizon]");
    const bool instant = spec_.info->knowledge == ccd::Knowledge::Instant;
    if (instant) t1 = t0;
    if (!(t1 >= t0 && t1 <= T)) throw ccd::InputError(who, "t1", "must be in [t0, horizon]");
    if (acceleration_bound && !(*acceleration_bound >= 0.0 && std::isfinite(*acceleration_bound)))
      throw ccd::InputError(who, "acceleration_bound", "must be finite and >= 0");
    std::vector<ccd::Aabb> boxes;
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      motion_ = scene->motion();
      scene_ = scene;
      ccd::StateCursor(motion_->centres()).evaluate(t0, states_);
      ccd::StepContext ctx;
      ctx.t0 = t0;
      ctx.t1 = t1;
      ctx.start = states_;
      ctx.motion = motion_.get();
      if (spec_.info->knowledge == ccd::Knowledge::Exact) ctx.exact = &motion_->centres();
      ctx.acceleration_bound = acceleration_bound.value_or(scene->scene().max_acceleration());
      ctx.walls = scene->scene().box;
      bound_->prepare(ctx, boxes);
    }
    const auto n = static_cast<py::ssize_t>(boxes.size());
    auto* heap = new std::vector<ccd::Aabb>(std::move(boxes));
    py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<ccd::Aabb>*>(p); });
    return py::array_t<double>({n, py::ssize_t{2}, py::ssize_t{3}},
                               reinterpret_cast<const double*>(heap->data()), owner);
  }

  py::tuple test_pairs(const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& pairs) {
    const std::string who = "Bound(" + name_ + ").test_pairs";
    if (!motion_) throw ccd::InputError(who, "", "call prepare(scene, t0, t1) first");
    if (pairs.ndim() != 2 || pairs.shape(1) != 2)
      throw ccd::InputError(who, "pairs", "must be an (m, 2) array");
    const auto m = static_cast<std::size_t>(pairs.shape(0));
    const std::uint32_t* p = pairs.data();
    for (std::size_t i = 0; i < m; ++i)
      if (p[2 * i] >= states_.size() || p[2 * i + 1] >= states_.size() || p[2 * i] == p[2 * i + 1])
        throw ccd::InputError(who, "pairs[" + std::to_string(i) + "]",
                              "must be two different bodies below " + std::to_string(states_.size()));
    py::array_t<bool> possible(static_cast<py::ssize_t>(m));
    py::array_t<double> earliest(static_cast<py::ssize_t>(m));
    bool* out_possible = possible.mutable_data();
    double* out_earliest = earliest.mutable_data();
    {
      py::gil_scoped_release release;
      std::lock_guard lock(mutex_);
      for (std::size_t i = 0; i < m; ++i) {
        const ccd::PairTest t = bound_->test(p[2 * i], p[2 * i + 1]);
        out_possible[i] = t.possible();
        out_earliest[i] = t.earliest;
      }
    }
    return py::make_tuple(possible, earliest);
  }

  const std::string& name() const { return name_; }
  const ccd::BoundSpec& spec() const { return spec_; }

 private:
  std::string name_;
  ccd::BoundSpec spec_;
  std::unique_ptr<ccd::Bound> bound_;
  std::shared_ptr<PyScene> scene_;  // what the last prepare saw
  std::shared_ptr<const ccd::RigidMotion> motion_;
  std::vector<ccd::BodyState> states_;
  std::mutex mutex_;
};

}  // namespace

void bind_bounds(py::module_& m) {
  py::class_<PyBound>(m, "Bound",
                      "A bound of the registry, e.g. Bound('capsule'), Bound('horn:4'), Bound('aabb')")
      .def(py::init<const std::string&>(), py::arg("spec"))
      .def("prepare", &PyBound::prepare, py::arg("scene"), py::arg("t0"), py::arg("t1") = 0.0,
           py::arg("acceleration_bound") = py::none(),
           "The (n, 2, 3) boxes of every body over [t0, t1] (an instant bound: at t0); "
           "acceleration_bound defaults to the scene's largest")
      .def("test_pairs", &PyBound::test_pairs, py::arg("pairs"),
           "The bound's own test of each pair after prepare: (possible bool array, earliest time array)")
      .def_property_readonly("name", &PyBound::name)
      .def_property_readonly(
          "knowledge", [](const PyBound& b) { return std::string(ccd::to_string(b.spec().info->knowledge)); })
      .def_property_readonly("conservative", [](const PyBound& b) { return b.spec().info->conservative; })
      .def_property_readonly("options",
                             [](const PyBound& b) { return to_python(b.spec().options.to_json()); })
      .def("__repr__", [](const PyBound& b) {
        return "<ccdlab.Bound " + b.name() + ": " + std::string(ccd::to_string(b.spec().info->knowledge)) + ", " +
               (b.spec().info->conservative ? "conservative" : "not conservative") + ", options " +
               b.spec().options.to_json().dump() + ">";
      });
}

}  // namespace ccdlab::python
