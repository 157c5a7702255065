#pragma once
// Writes a triangle mesh as a PLY file: `element vertex` with x, y, z (double or float),
// `element face` with `list uchar int vertex_indices` (`uint` beyond 2^31 - 1 vertices).
// Ascii values are the shortest decimals that read back to the same double or float
// (std::to_chars), so every encoding reads back (ply_reader.hpp) bit for bit; float
// coordinates are the doubles rounded to the nearest float.
#include <cloth/io/ply_header.hpp>
#include <cloth/io/triangle_mesh.hpp>

#include <string>

namespace ccd::cloth {

enum class PlyScalar : std::uint8_t { Double, Float };

struct PlyEncoding {
  PlyFormat format = PlyFormat::BinaryLittleEndian;
  PlyScalar coordinates = PlyScalar::Double;
};

/// The bytes of the PLY file. Throws std::invalid_argument when the mesh cannot be written
/// so that it reads back: a NaN or infinite coordinate, a coordinate beyond the float range
/// with PlyScalar::Float, a vertex index out of range.
std::string format_ply(const TriangleMesh& mesh, PlyEncoding encoding = {});

/// Writes format_ply(mesh, encoding) to `path` atomically (ccd/io/atomic_file.hpp): the old
/// file or the whole new one, never a part. Throws InputError when `path` is refused.
void write_ply(const std::string& path, const TriangleMesh& mesh, PlyEncoding encoding = {});

}  // namespace ccd::cloth
