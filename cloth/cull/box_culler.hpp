#pragma once
// `boxes:<broad phase>`: the primitives' swept boxes (cloth/cull/primitive_boxes.hpp,
// widened by half the separation) through any broad phase of the sphere pipeline's
// registry (ccd/broad_phase/registry.hpp), then typed candidates. Two broad-phase
// instances are kept between calls (so coherent methods such as `sap` update
// incrementally): one over the vertices and the triangles, whose vertex-triangle pairs are
// the vertex-face candidates, and one over the edges, for the edge-edge candidates.
// Adjacent pairs are dropped. Conservative: a broad phase reports every overlapping pair,
// and primitives that come within the separation have overlapping boxes.
#include <cloth/cull/culler.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <memory>

namespace ccd::cloth {

class BoxCuller final : public Culler {
 public:
  explicit BoxCuller(const BroadPhaseSpec& spec);
  std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                              double separation) override;
  /// "box_pairs": the pairs both broad phases reported.
  std::vector<CullerCounter> counters() const override { return {{"box_pairs", box_pairs_}}; }

 private:
  std::unique_ptr<BroadPhase> vertex_face_, edge_edge_;
  std::vector<Aabb> vertex_boxes_, boxes_;
  std::vector<BodyPair> pairs_;
  std::uint64_t box_pairs_ = 0;
};

}  // namespace ccd::cloth
