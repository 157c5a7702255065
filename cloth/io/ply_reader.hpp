#pragma once
// PLY mesh frames: the vertex positions and the triangles of a PLY file (ascii, binary
// little- or big-endian; header in ply_header.hpp).
//
// Read: the element `vertex` with the scalar properties x, y, z of any type (float and
// double are read exactly, floats widened to doubles; integer types give their value);
// the element `face` with the list property `vertex_indices` (or `vertex_index`) of any
// integer count and item types. Every other property (colours, normals, texture
// coordinates, lists) of these two elements and every other element (edges, materials...),
// before or after them, is checked against its declared types and skipped. In ascii, each
// element is one line (blank lines between them are skipped), values are decimal numbers
// of the declared type, and nothing but white space may follow the last element.
//
// Refused, with an InputError naming the file and the element and its index
// (`t1.ply: face 17: vertex index 9001 out of range (the file has 9001 vertices)`):
// anything parse_ply_header refuses; no vertex or no face element, or one without x, y, z
// or vertex_indices; counts whose smallest encoding exceeds the bytes after the header
// (checked before anything is allocated); a body that ends early (the element and index
// where it ran out); a value that is not a number of the declared type or outside its
// range; NaN or infinite coordinates (`vertex 12: z is NaN`); a face of other than 3
// vertices; a negative or out-of-range vertex index; text after the last element (ascii);
// bytes after the last element (binary).
#include <cloth/io/triangle_mesh.hpp>

#include <string>
#include <string_view>

namespace ccd::cloth {

/// Parses the bytes of a PLY file; `file` names it in errors. Throws InputError.
TriangleMesh parse_ply(std::string_view bytes, const std::string& file);
/// Reads the PLY file at `path` (a regular file). Throws InputError.
TriangleMesh read_ply(const std::string& path);

}  // namespace ccd::cloth
