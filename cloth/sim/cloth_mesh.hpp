#pragma once
// The triangle mesh and the springs of a grid cloth. Quad (i, j) is split along its
// diagonal from (i, j) to (i+1, j+1). Springs: structural between grid neighbours,
// shear along both diagonals of each quad, bend between particles two apart along a row or
// a column (the 2-neighbourhood stencil). Rest lengths are the initial distances.
#include <cloth/sim/cloth_scene.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace ccd::cloth {

enum class SpringKind : std::uint8_t { Structural, Shear, Bend };

struct Spring {
  std::uint32_t a, b;
  double rest;
  SpringKind kind;
};

struct ClothMesh {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 2>> edges;  ///< each mesh edge once (a < b)
  std::vector<Spring> springs;
  /// Optional: planar coordinates of each vertex in which the triangles form an embedded,
  /// positively oriented triangulation of a convex region (a grid cloth: the indices (i, j)).
  /// Empty when unknown. The `bvh_cones` culler needs it to skip a self-test
  /// (cloth/cull/triangle_bvh.hpp).
  std::vector<std::array<double, 2>> chart;
};

/// The particles' initial positions, in index order i + nx j.
std::vector<Vec3> initial_positions(const ClothScene& s);
ClothMesh make_grid_mesh(const ClothScene& s);

}  // namespace ccd::cloth
