#pragma once
// `bvh` and `bvh_cones` as cullers that keep their hierarchy between check intervals
// (cloth/cull/triangle_bvh.hpp): the first call builds the topology from x0; later calls
// refit it to the new interval; it is rebuilt from the interval's x0 when its quality
// degrades. The rule: the tree's quality (summed surface areas of the internal nodes'
// boxes over the root's: the surface area heuristic's cost of a traversal) is recorded
// right after each build; when a refit makes it exceed `kRebuildFactor` times that value,
// the topology is rebuilt (and refitted).
// A call with another mesh (different triangles or edges) or vertex count starts afresh.
//
// Refit or rebuild, `bvh` returns the same candidates (every non-adjacent pair whose
// primitive boxes overlap): the topology changes only its speed. `bvh_cones` drops the
// pairs inside nodes with a narrow normal cone, so its output depends on the topology.
#include <cloth/cull/culler.hpp>
#include <cloth/cull/triangle_bvh.hpp>

#include <memory>

namespace ccd::cloth {

class BvhCuller final : public Culler {
 public:
  static constexpr double kRebuildFactor = 1.5;
  explicit BvhCuller(bool cones) : cones_(cones) {}
  std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                              double separation) override;
  /// As cull, with only the pairs of primitives that both have an active vertex (one flag
  /// per vertex; see TriangleBvh::self_candidates).
  std::vector<Candidate> cull_active(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                     double separation, std::span<const std::uint8_t> active);
  /// "rebuilt" (1 when this call built the topology), "node_pairs", "cone_culled".
  std::vector<CullerCounter> counters() const override;

 private:
  bool cones_;
  ClothMesh mesh_;  // the tree's own copy of the topology it was built for
  std::unique_ptr<TriangleBvh> tree_;
  double built_quality_ = 0;
  bool rebuilt_ = false;
  BvhStats stats_;
};

}  // namespace ccd::cloth
