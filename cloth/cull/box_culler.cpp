#include "box_culler.hpp"

#include <cloth/cull/primitive_boxes.hpp>

#include <algorithm>
#include <stdexcept>

namespace ccd::cloth {

BoxCuller::BoxCuller(const BroadPhaseSpec& spec) : vertex_face_(spec.make()), edge_edge_(spec.make()) {}

std::vector<Candidate> BoxCuller::cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                       double separation) {
  if (x0.size() != x1.size()) throw std::invalid_argument("boxes culler: x0 and x1 differ in size");
  for (std::size_t i = 0; i < x0.size(); ++i)
    if (!x0[i].allFinite() || !x1[i].allFinite())
      throw std::invalid_argument("boxes culler: positions must be finite");
  vertex_boxes(x0, x1, separation / 2, vertex_boxes_);
  const auto vertices = static_cast<std::uint32_t>(x0.size());
  std::vector<Candidate> out;
  box_pairs_ = 0;

  boxes_.assign(vertex_boxes_.begin(), vertex_boxes_.end());
  for (const auto& t : mesh.triangles) boxes_.push_back(triangle_box(vertex_boxes_, t));
  vertex_face_->find_pairs(boxes_, pairs_);
  box_pairs_ += pairs_.size();
  for (const BodyPair& p : pairs_) {
    if (p.a >= vertices || p.b < vertices) continue;  // vertex-vertex or triangle-triangle
    const Candidate c{PrimitivePair::VertexFace, p.a, p.b - vertices};
    if (!adjacent(mesh, c)) out.push_back(c);
  }

  boxes_.clear();
  for (const auto& e : mesh.edges) boxes_.push_back(edge_box(vertex_boxes_, e));
  edge_edge_->find_pairs(boxes_, pairs_);
  box_pairs_ += pairs_.size();
  for (const BodyPair& p : pairs_) {
    const Candidate c{PrimitivePair::EdgeEdge, p.a, p.b};
    if (!adjacent(mesh, c)) out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ccd::cloth
