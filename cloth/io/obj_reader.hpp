#pragma once
// Wavefront OBJ mesh frames: the vertex positions and triangles of an OBJ file.
//
// Read: `v x y z` with an optional weight w (`v x y z w`, ignored) or a vertex colour
// (`v x y z r g b`, ignored); `f` with three vertices written `a`, `a/b`, `a//c` or
// `a/b/c` (a the vertex, 1-based, or negative: relative to the vertices defined so far;
// b and c, texture and normal indices, are checked as integers and ignored). Skipped:
// `vt`, `vn`, `vp`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p` and the other statements
// of the format (curves, surfaces, display attributes), comments (`#` to the end of the
// line), blank lines. Lines end in "\n" or "\r\n"; a line ending in `\` continues on the
// next.
//
// Refused, with an InputError naming the file and the line
// (`frame.obj: line 42: face has 4 vertices; only triangles are read`): an empty file; an
// unknown statement; a vertex with other than 3, 4, 6 or 7 numbers, a value that is not a
// decimal number or beyond the range of a double, NaN or infinite coordinates (`line 12: z
// is NaN`); a face of other than 3 vertices; a vertex index 0, out of range (positive
// indices may name vertices defined later in the file), or not an integer; a file with no
// vertex.
#include <cloth/io/triangle_mesh.hpp>

#include <string>
#include <string_view>

namespace ccd::cloth {

/// Parses the text of an OBJ file; `file` names it in errors. Throws InputError.
TriangleMesh parse_obj(std::string_view text, const std::string& file);
/// Reads the OBJ file at `path` (a regular file). Throws InputError.
TriangleMesh read_obj(const std::string& path);

}  // namespace ccd::cloth
