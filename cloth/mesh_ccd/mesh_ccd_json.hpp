#pragma once
// A mesh CCD result as `ccdlab-mesh-ccd/1` JSON (docs/formats.md): what `ccdlab ccd FRAME0
// FRAME1` writes and `ccdlab.mesh_ccd` returns. The command adds the frame files, the
// reading time and the peak memory.
#include <cloth/mesh_ccd/mesh_ccd.hpp>

#include <nlohmann/json.hpp>

namespace ccd::cloth {

/// `threads` is the thread count that ran (recorded; the results do not depend on it).
nlohmann::json mesh_ccd_json(const MeshCcdResult& result, const MeshCcdOptions& options, unsigned threads);

}  // namespace ccd::cloth
