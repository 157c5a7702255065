// The compiled part of the `ccdlab` Python package (python/ccdlab/__init__.py re-exports it):
// scenes, generators, ground truth, the broad phases and bounds over numpy arrays, mesh CCD
// and whole experiments (docs/python.md).
#include "bindings.hpp"

PYBIND11_MODULE(_ccdlab, m) {
  using namespace ccdlab::python;
  m.doc() =
      "ccdlab: continuous collision detection (scenes of spheres and rigid bodies, scenery, "
      "certified ground truth, bounds, broad phases, experiments, mesh CCD)";
  m.attr("__version__") = CCDLAB_VERSION;
  bind_errors(m);
  bind_scene(m);
  bind_truth(m);
  bind_broad_phases(m);
  bind_bounds(m);
  bind_run(m);
  bind_mesh_ccd(m);
  bind_queries(m);
  bind_rigid_queries(m);
  bind_import(m);
}
