#pragma once
// The pieces of the `ccdlab` Python module (module.cpp puts them together). Each
// bind_* function adds one concept's classes and functions to the module.
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ccdlab::python {

namespace py = pybind11;

/// A scene and, built on first use, its motion: the exact trajectories and the shapes and
/// spin on them (shared with the bounds that were prepared on it).
class PyScene {
 public:
  explicit PyScene(ccd::Scene scene, std::string source)
      : scene_(std::move(scene)), source_(std::move(source)) {}
  const ccd::Scene& scene() const { return scene_; }
  const std::string& source() const { return source_; }
  /// The exact motion; built once (walls solved), safe to call without the GIL.
  std::shared_ptr<const ccd::Trajectories> trajectories() const;
  /// The scene's motion (centres = trajectories(), shapes, spin); built once, safe to call
  /// without the GIL. It keeps the trajectories alive.
  std::shared_ptr<const ccd::RigidMotion> motion() const;

 private:
  ccd::Scene scene_;
  std::string source_;  ///< a file name, or "ccdlab.generate(NAME)", for error messages
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const ccd::Trajectories> trajectories_;
  mutable std::shared_ptr<const ccd::RigidMotion> motion_;
};

/// A numpy array that owns `values` (moved, not copied), with the given shape.
template <class T>
py::array_t<T> owning_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* heap = new std::vector<T>(std::move(values));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, heap->data(), owner);
}

/// JSON between C++ and Python: nlohmann's text and Python's json module (both round-trip
/// doubles exactly).
py::object to_python(const nlohmann::json& j);
nlohmann::json from_python(const py::handle& obj, const std::string& what);

void bind_errors(py::module_& m);
void bind_scene(py::module_& m);
void bind_truth(py::module_& m);
void bind_broad_phases(py::module_& m);
void bind_bounds(py::module_& m);
void bind_run(py::module_& m);
void bind_mesh_ccd(py::module_& m);
void bind_queries(py::module_& m);
void bind_rigid_queries(py::module_& m);
void bind_import(py::module_& m);

}  // namespace ccdlab::python
