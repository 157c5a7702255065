#pragma once
// Writes a triangle mesh as a Wavefront OBJ file: one `v x y z` line per vertex (the
// shortest decimals that read back to the same doubles, std::to_chars) and one `f a b c`
// line per face (1-based indices). obj_reader.hpp reads it back bit for bit.
#include <cloth/io/triangle_mesh.hpp>

#include <string>

namespace ccd::cloth {

/// The text of the OBJ file. Throws std::invalid_argument for a NaN or infinite coordinate
/// or a vertex index out of range.
std::string format_obj(const TriangleMesh& mesh);

/// Writes format_obj(mesh) to `path` atomically (ccd/io/atomic_file.hpp). Throws
/// InputError when `path` is refused.
void write_obj(const std::string& path, const TriangleMesh& mesh);

}  // namespace ccd::cloth
