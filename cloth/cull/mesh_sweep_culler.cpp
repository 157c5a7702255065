#include "mesh_sweep_culler.hpp"

#include <cloth/mesh_ccd/mesh_sweep.hpp>

#include <stdexcept>

namespace ccd::cloth {

std::vector<Candidate> MeshSweepCuller::cull(const ClothMesh& mesh, std::span<const Vec3> x0,
                                             std::span<const Vec3> x1, double separation) {
  for (std::size_t i = 0; i < x0.size(); ++i)
    if (!x0[i].allFinite() || (i < x1.size() && !x1[i].allFinite()))
      throw std::invalid_argument("mesh_sweep culler: positions must be finite");
  MeshSweep sweep;
  sweep.prepare(mesh, x0, x1, {separation, true, 1});
  return sweep.all(1);
}

}  // namespace ccd::cloth
