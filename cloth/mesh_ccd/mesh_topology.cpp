#include "mesh_topology.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ccd::cloth {

ClothMesh mesh_topology(std::span<const std::array<std::uint32_t, 3>> faces, std::size_t vertex_count) {
  if (vertex_count > 0xffffffffu) throw std::invalid_argument("more than 2^32 - 1 vertices");
  ClothMesh mesh;
  mesh.triangles.assign(faces.begin(), faces.end());
  mesh.edges.reserve(3 * faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& t = faces[f];
    for (int k = 0; k < 3; ++k) {
      if (t[static_cast<std::size_t>(k)] >= vertex_count)
        throw std::invalid_argument("face " + std::to_string(f) + ": vertex index " +
                                    std::to_string(t[static_cast<std::size_t>(k)]) + " out of range (" +
                                    std::to_string(vertex_count) + " vertices)");
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw std::invalid_argument("face " + std::to_string(f) + ": vertex " +
                                  std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]) + " repeated");
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      mesh.edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(mesh.edges.begin(), mesh.edges.end());
  mesh.edges.erase(std::unique(mesh.edges.begin(), mesh.edges.end()), mesh.edges.end());
  return mesh;
}

}  // namespace ccd::cloth
