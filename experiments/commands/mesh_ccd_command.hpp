#pragma once
// `ccdlab ccd FRAME0 FRAME1 ...`: mesh CCD between two frame files (mesh_ccd.cpp). The
// `ccd` command (ccd.cpp) hands its arguments here when a positional argument is a mesh
// file: a name ending in .ply or .obj (any case), or a file whose first line is `ply`.
#include <span>
#include <string>

namespace ccdlab {

/// True when `args` (those of `ccdlab ccd`) name a mesh frame file.
bool is_mesh_ccd_call(std::span<const std::string> args);

/// Runs the mesh mode; the exit status (0, 1, or 2 for bad input or usage).
int run_mesh_ccd(std::span<const std::string> args);

}  // namespace ccdlab
