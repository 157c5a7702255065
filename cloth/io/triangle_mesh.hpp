#pragma once
// A triangle mesh as a frame file holds it: vertex positions and triangles of vertex
// indices (0-based, in file order, each below vertices.size()). Nothing else of the file
// (colours, normals, texture coordinates, groups) is kept.
#include <ccd/geometry/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace ccd::cloth {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

}  // namespace ccd::cloth
