#pragma once
// `ccdlab ccd FRAME0 FRAME1 ...`: mesh CCD between two frame files (mesh_ccd.cpp). The
// `ccd` command (ccd.cpp) parses the arguments of both modes and runs this one when a
// positional argument is a mesh file: a name ending in .ply or .obj (any case), or a file
// whose first line is `ply`.
#include <cloth/mesh_ccd/mesh_ccd.hpp>

#include <string>

namespace ccdlab {

/// What `ccdlab ccd FRAME0 FRAME1 [options]` was given.
struct MeshCcdArgs {
  std::string frame0, frame1, out_path;
  ccd::cloth::MeshCcdOptions options;
  bool quiet = false;
};

/// True when `path` names a mesh frame file.
bool is_mesh_file(const std::string& path);

/// Runs the mesh mode; the exit status (0, 1, or 2 for bad input).
int run_mesh_ccd(MeshCcdArgs p);

}  // namespace ccdlab
