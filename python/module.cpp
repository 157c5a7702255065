// The `ccdlab` Python module: scenes, generators, ground truth, the broad phases and
// bounds over numpy arrays, and whole experiments (README.md, "Python").
#include "bindings.hpp"

PYBIND11_MODULE(ccdlab, m) {
  using namespace ccdlab::python;
  m.doc() =
      "ccdlab: continuous collision detection of spheres and rigid bodies among static scenery, and of "
      "triangle meshes (scenes, exact ground truth, bounds, broad phases, experiments, mesh CCD)";
  m.attr("__version__") = CCDLAB_VERSION;
  bind_errors(m);
  bind_scene(m);
  bind_truth(m);
  bind_broad_phases(m);
  bind_bounds(m);
  bind_run(m);
  bind_mesh_ccd(m);
}
