#pragma once
// Mesh frame files, PLY or Wavefront OBJ, and pairs of frames of one moving mesh.
//
// The format is chosen by content, then by name: a file whose first line is `ply` is read
// as PLY (ply_reader.hpp); any other file named *.ply (any case) is refused as a PLY file
// without its first line; every other file is read as OBJ (obj_reader.hpp).
#include <cloth/io/triangle_mesh.hpp>

#include <string>

namespace ccd::cloth {

/// Reads the mesh at `path`. Throws InputError naming `path`.
TriangleMesh read_mesh(const std::string& path);

/// Two frames of one mesh: positions at the start and the end of the step, one face list.
struct MeshFrames {
  std::vector<Vec3> vertices0, vertices1;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

/// Reads two frames and checks that they are frames of one mesh: the same number of
/// vertices and the same faces in the same order. Throws InputError naming the file and
/// what differs (`t1.ply: face 17: (4, 5, 9) differs from t0.ply's face 17 (4, 5, 6)`).
/// With threads >= 2 the two files are read at once; the error reported is the same
/// (the first frame's, if both are bad).
MeshFrames read_mesh_frames(const std::string& path0, const std::string& path1, unsigned threads = 1);

/// The same check on meshes already read (`name0`, `name1` name them in errors).
MeshFrames mesh_frames(TriangleMesh frame0, TriangleMesh frame1, const std::string& name0, const std::string& name1);

}  // namespace ccd::cloth
