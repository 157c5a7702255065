#pragma once
// `mesh_sweep` as a culler of the registry (cloth/cull/cullers.hpp): the broad phase of
// cloth/mesh_ccd/mesh_sweep.hpp on one thread, with its half-interval filter, every
// candidate returned at once. The mesh CCD pipeline (cloth/mesh_ccd/mesh_ccd.hpp) runs the
// same sweep on several threads and streams its candidates instead.
#include <cloth/cull/culler.hpp>

namespace ccd::cloth {

class MeshSweepCuller final : public Culler {
 public:
  std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                              double separation) override;
};

}  // namespace ccd::cloth
