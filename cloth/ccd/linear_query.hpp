#pragma once
// One continuous collision query between two mesh primitives under linear motion, in the
// row order of the public CCD benchmark (Wang et al. 2021): four points at t = 0, then the
// same four points at t = 1. Each point moves on the segment between its two positions
// over the normalised time t in [0, 1].
//
//   vertex-face: x[0] = vertex, x[1..3] = triangle corners (t = 0); x[4..7] at t = 1.
//   edge-edge:   x[0], x[1] = edge a, x[2], x[3] = edge b (t = 0); x[4..7] at t = 1.
//
// Primitives are closed sets: a vertex on a triangle's edge or an edge through another
// edge's end point is a contact. A triangle or edge may be degenerate (collinear corners,
// zero length): it is then the closed convex hull of its points.
#include <ccd/geometry/vec3.hpp>

#include <array>
#include <cstdint>
#include <string_view>

namespace ccd::cloth {

enum class PrimitivePair : std::uint8_t { VertexFace, EdgeEdge };

/// "vf", "ee".
constexpr std::string_view to_string(PrimitivePair k) { return k == PrimitivePair::VertexFace ? "vf" : "ee"; }

struct LinearQuery {
  std::array<Vec3, 8> x{};

  const Vec3& at_start(int i) const { return x[static_cast<std::size_t>(i)]; }
  const Vec3& at_end(int i) const { return x[static_cast<std::size_t>(i + 4)]; }
};

}  // namespace ccd::cloth
