#pragma once
// The CCD primitives of a triangle mesh given by its faces: the faces as triangles and every
// edge once (a < b), sorted, as the cullers (cloth/cull/culler.hpp) take them. Vertices are
// indices into the mesh's position arrays; no chart is known (`bvh_cones` then skips no
// self-test).
#include <cloth/sim/cloth_mesh.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace ccd::cloth {

/// Throws std::invalid_argument naming the face ("face 17: vertex index 9001 out of range
/// (3 vertices)", "face 4: vertex 2 repeated") when a face has an index >= vertex_count or
/// names a vertex twice, and when vertex_count does not fit in 32 bits.
ClothMesh mesh_topology(std::span<const std::array<std::uint32_t, 3>> faces, std::size_t vertex_count);

}  // namespace ccd::cloth
