#pragma once
// The checks a mesh passes before it is written, so that every file written reads back:
// finite coordinates (and within the float range when written as floats), vertex indices
// below the number of vertices.
#include <cloth/io/triangle_mesh.hpp>

namespace ccd::cloth {

/// Throws std::invalid_argument naming `writer`, the vertex or face and what is wrong.
void check_mesh_for_writing(const TriangleMesh& mesh, bool as_float, const char* writer);

}  // namespace ccd::cloth
