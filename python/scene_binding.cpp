// ccdlab.Scene, ccdlab.load_scene, ccdlab.scene_from_json, ccdlab.generate.
#include "bindings.hpp"
#include "interruptible.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>
#include <generators/registry.hpp>

#include <ccd/util/parameters.hpp>

#include <algorithm>
#include <stdexcept>

namespace ccdlab::python {

std::shared_ptr<const ccd::Trajectories> PyScene::trajectories() const {
  std::lock_guard lock(mutex_);
  if (!trajectories_) {
    try {
      trajectories_ = std::make_shared<const ccd::Trajectories>(scene_);
    } catch (const ccd::TooManyPieces& err) {
      throw ccd::InputError(
          source_, "bodies[" + std::to_string(err.body()) + "]",
          "needs more than " + std::to_string(err.limit()) +
              " trajectory pieces over the horizon (wall reflections and acceleration changes)");
    }
  }
  return trajectories_;
}

std::shared_ptr<const ccd::RigidMotion> PyScene::motion() const {
  std::shared_ptr<const ccd::Trajectories> centres = trajectories();
  std::lock_guard lock(mutex_);
  if (!motion_) {
    // The motion refers to the trajectories: the deleter keeps them alive with it.
    auto* m = new ccd::RigidMotion(scene_, *centres);
    motion_ = std::shared_ptr<const ccd::RigidMotion>(m, [centres](const ccd::RigidMotion* p) { delete p; });
  }
  return motion_;
}

namespace {

// One Vec3 per body, as an (n, 3) array.
template <class Get>
py::array_t<double> per_body(const ccd::Scene& s, Get get) {
  std::vector<double> v;
  v.reserve(3 * s.bodies.size());
  for (const ccd::Body& b : s.bodies) {
    const ccd::Vec3& x = get(b);
    v.insert(v.end(), {x.x(), x.y(), x.z()});
  }
  return owning_array(std::move(v), {static_cast<py::ssize_t>(s.bodies.size()), 3});
}

// The times as pybind11's list conversion reads them, with its failures named: a 0-d array
// passes its sequence check and then fails len() with a bare "len() of unsized object".
std::vector<double> times_of(const py::object& times) {
  // An array of two or more dimensions would be read row by row, each row through float():
  // [[0.5]] would pass as [0.5].
  if (py::isinstance<py::array>(times) && times.cast<py::array>().ndim() > 1)
    throw py::type_error("Scene.positions: times must be a one-dimensional sequence of numbers, got an array of " +
                         std::to_string(times.cast<py::array>().ndim()) + " dimensions");
  try {
    return times.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
  } catch (const py::error_already_set& err) {
    if (!err.matches(PyExc_TypeError)) throw;
  }
  throw py::type_error("Scene.positions: times must be a sequence of numbers, got " +
                       py::repr(times).cast<std::string>().substr(0, 80));
}

py::array_t<double> positions(const PyScene& self, const py::object& times_object) {
  const std::vector<double> times = times_of(times_object);
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] >= 0.0 && times[i] <= self.scene().horizon))
      throw ccd::InputError("positions", "times[" + std::to_string(i) + "]",
                            "must be in [0, horizon = " + std::to_string(self.scene().horizon) + "]");
  const std::size_t n = self.scene().bodies.size();
  std::vector<double> out;
  {
    py::gil_scoped_release release;
    const auto traj = self.trajectories();
    out.resize(times.size() * n * 3);
    for (std::size_t k = 0; k < times.size(); ++k)
      for (std::size_t b = 0; b < n; ++b) {
        const ccd::Vec3 p = traj->position(b, times[k]);
        for (int c = 0; c < 3; ++c) out[(k * n + b) * 3 + c] = p[c];
      }
  }
  return owning_array(std::move(out),
                      {static_cast<py::ssize_t>(times.size()), static_cast<py::ssize_t>(n), 3});
}

/// "<ccdlab.Scene 4 bodies (3 shaped), 2 scenery polygons, box (wrap), horizon 2 s, from rigid.json>".
std::string scene_repr(const PyScene& self) {
  const ccd::Scene& s = self.scene();
  std::string out = "<ccdlab.Scene " + std::to_string(s.bodies.size()) + " bodies";
  const auto shaped = std::count_if(s.rigid.begin(), s.rigid.end(),
                                    [](const ccd::RigidBody& r) { return r.shape != ccd::kNoShape; });
  if (shaped) out += " (" + std::to_string(shaped) + " shaped)";
  if (!s.scenery.empty()) out += ", " + std::to_string(s.scenery.size()) + " scenery polygons";
  if (s.box) out += s.wraps() ? ", box (wraps)" : ", box";
  if (!s.gravity.isZero(0.0)) out += ", gravity";
  out += ", horizon " + ccd::format_number(s.horizon) + " s, from " + self.source() + ">";
  return out;
}

std::shared_ptr<PyScene> generate(const std::string& name, const py::kwargs& params) {
  const std::string source = "ccdlab.generate(" + name + ")";
  nlohmann::json j = from_python(params, source);
  return run_interruptible([&]() {
    try {
      return std::make_shared<PyScene>(generate_scene(name, j), source);
    } catch (const std::invalid_argument& err) {
      throw ccd::InputError(source, "", err.what());
    }
  });
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<PyScene, std::shared_ptr<PyScene>>(
      m, "Scene", "Spheres with exact piecewise-quadratic motion (ccdlab-scene/1)")
      .def("__len__", [](const PyScene& s) { return s.scene().bodies.size(); })
      .def_property_readonly("horizon", [](const PyScene& s) { return s.scene().horizon; })
      .def_property_readonly("gravity",
                             [](const PyScene& s) {
                               const ccd::Vec3& g = s.scene().gravity;
                               return py::make_tuple(g.x(), g.y(), g.z());
                             })
      .def_property_readonly(
          "radius",
          [](const PyScene& s) {
            std::vector<double> r;
            for (const ccd::Body& b : s.scene().bodies) r.push_back(b.radius);
            const auto n = static_cast<py::ssize_t>(r.size());
            return owning_array(std::move(r), {n});
          },
          "(n,) radii, a copy")
      .def_property_readonly(
          "position",
          [](const PyScene& s) {
            return per_body(s.scene(), [](const ccd::Body& b) -> const ccd::Vec3& { return b.position; });
          },
          "(n, 3) positions at t = 0, a copy")
      .def_property_readonly(
          "velocity",
          [](const PyScene& s) {
            return per_body(s.scene(), [](const ccd::Body& b) -> const ccd::Vec3& { return b.velocity; });
          },
          "(n, 3) velocities at t = 0, a copy")
      .def_property_readonly(
          "acceleration",
          [](const PyScene& s) {
            return per_body(s.scene(), [](const ccd::Body& b) -> const ccd::Vec3& { return b.acceleration; });
          },
          "(n, 3) own accelerations at t = 0 (gravity not included), a copy")
      .def_property_readonly("max_acceleration",
                             [](const PyScene& s) { return s.scene().max_acceleration(); })
      .def(
          "to_json", [](const PyScene& s) { return to_python(ccd::scene_to_json(s.scene())); },
          "The scene as a ccdlab-scene/1 dict")
      .def(
          "save", [](const PyScene& s, const std::string& path) { ccd::save_scene(s.scene(), path); },
          py::arg("path"), "Writes the scene file atomically")
      .def("positions", &positions, py::arg("times"),
           "(len(times), n, 3) exact centre positions at the given times (walls solved)")
      .def("__repr__", &scene_repr);

  m.def(
      "load_scene",
      [](const std::string& path) {
        return run_interruptible([&]() { return std::make_shared<PyScene>(ccd::load_scene(path), path); });
      },
      py::arg("path"),
      "Reads and validates a scene file: JSON (ccdlab-scene/1 or /2) or binary (ccdlab-scene-binary/1, ccdlab pack) "
      "(errors: ccdlab.InputError)");
  m.def(
      "scene_from_json",
      [](const py::object& j) {
        return std::make_shared<PyScene>(ccd::scene_from_json(from_python(j, "scene"), "scene"), "scene");
      },
      py::arg("scene"), "A scene from a ccdlab-scene/1 dict (as to_json returns)");
  m.def("generate", &generate, py::arg("name"),
        "A generated scene: generate('gas', bodies=500, seed=7) (the generators of `ccdlab scene`)");
  m.def("generators", []() {
    py::list out;
    for (const Generator& g : generators()) out.append(py::str(std::string(g.name)));
    return out;
  });
}

}  // namespace ccdlab::python
