#include "bvh_culler.hpp"

#include <stdexcept>

namespace ccd::cloth {

std::vector<Candidate> BvhCuller::cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                       double separation) {
  return cull_active(mesh, x0, x1, separation, {});
}

std::vector<Candidate> BvhCuller::cull_active(const ClothMesh& mesh, std::span<const Vec3> x0,
                                              std::span<const Vec3> x1, double separation,
                                              std::span<const std::uint8_t> active) {
  if (x0.size() != x1.size()) throw std::invalid_argument("bvh culler: x0 and x1 differ in size");
  rebuilt_ = false;
  if (!tree_ || tree_->vertex_count() != x0.size() || mesh_.triangles != mesh.triangles || mesh_.edges != mesh.edges ||
      mesh_.chart != mesh.chart) {
    mesh_.triangles = mesh.triangles;
    mesh_.edges = mesh.edges;
    mesh_.chart = mesh.chart;
    tree_ = std::make_unique<TriangleBvh>(mesh_, x0);
    rebuilt_ = true;
  }
  tree_->refit(x0, x1, separation / 2);
  if (!rebuilt_ && tree_->quality() > kRebuildFactor * built_quality_) {
    tree_->rebuild(x0);
    tree_->refit(x0, x1, separation / 2);
    rebuilt_ = true;
  }
  if (rebuilt_) built_quality_ = tree_->quality();
  return tree_->self_candidates(cones_, &stats_, active);
}

std::vector<CullerCounter> BvhCuller::counters() const {
  return {{"rebuilt", rebuilt_ ? 1u : 0u}, {"node_pairs", stats_.node_pairs}, {"cone_culled", stats_.cone_culled}, {"cone_rejected", stats_.cone_rejected}};
}

}  // namespace ccd::cloth
