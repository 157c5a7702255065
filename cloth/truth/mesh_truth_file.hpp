#pragma once
// The mesh truth stored in a file (`ccdlab-cloth-truth/1`, docs/cloth.md#mesh-truth), so
// that the expensive part of a cloth experiment is computed once per motion.
//
// A file names the motion it belongs to by a digest: SHA-256 of the mesh's triangles and
// edges, every frame's coordinates (their IEEE-754 bits) and the thickness. A truth is
// reused only when that digest matches, so a changed scene, step count, simulator or
// thickness never reuses a stale truth.
//
//   {"format": "ccdlab-cloth-truth/1", "digest": "<64 hex>", "thickness": 0.005,
//    "steps": S, "step_contacts": [[kind, a, b, kind, a, b, ...], ...],   // S lists
//    "state_contacts": [[...], ...]}                                      // S + 1 lists
// with kind 0 for vertex-face, 1 for edge-edge.
#include <cloth/truth/mesh_truth.hpp>

#include <nlohmann/json.hpp>

#include <span>
#include <string>
#include <vector>

namespace ccd::cloth {

inline constexpr const char* kMeshTruthFormat = "ccdlab-cloth-truth/1";

/// The digest of a motion (64 lowercase hexadecimal digits).
std::string motion_digest(const ClothMesh& mesh, std::span<const std::vector<Vec3>> frames, double thickness);

nlohmann::json mesh_truth_to_json(const MeshTruth& truth, const std::string& digest);

/// Reads a truth back, checked strictly against `mesh` (indices in range, pairs not
/// adjacent, lists sorted) and `digest`; throws InputError naming `file` and the field.
MeshTruth mesh_truth_from_json(const nlohmann::json& j, const std::string& file, const ClothMesh& mesh,
                               std::size_t vertex_count, const std::string& digest);

}  // namespace ccd::cloth
