#pragma once
// Typed self-collision candidates of a triangle mesh, and the brute-force reference.
//
// A candidate is a vertex-face pair (a vertex, b triangle) or an edge-edge pair (a < b,
// edge indices into ClothMesh::edges). Adjacent primitives are never candidates: a vertex
// of the triangle, or two edges sharing a vertex, touch by construction.
#include <cloth/ccd/linear_query.hpp>
#include <cloth/sim/cloth_mesh.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd::cloth {

struct Candidate {
  PrimitivePair kind;
  std::uint32_t a, b;
  friend bool operator==(const Candidate&, const Candidate&) = default;
  friend auto operator<=>(const Candidate&, const Candidate&) = default;
};

/// True when the two primitives share a vertex.
bool adjacent(const ClothMesh& mesh, const Candidate& c);

/// Every non-adjacent vertex-face and edge-edge pair, sorted (the reference of every culler).
std::vector<Candidate> brute_force_candidates(const ClothMesh& mesh, std::size_t vertex_count);

/// The CCD query of a candidate for the motion from x0 to x1 (one check interval).
LinearQuery candidate_query(const ClothMesh& mesh, const Candidate& c, std::span<const Vec3> x0,
                            std::span<const Vec3> x1);

}  // namespace ccd::cloth
