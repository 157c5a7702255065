#pragma once
// Mesh CCD between two frames: which vertex-face and edge-edge pairs of a triangle mesh
// come within the separation of each other while every vertex moves on a straight line
// from its position in frame 0 (t = 0) to frame 1 (t = 1), and the earliest time of impact.
//
// Stages: the primitives (cloth/mesh_ccd/mesh_topology.hpp), their swept boxes (built on
// the threads), the broad phase (a culler of the registry, cloth/cull/cullers.hpp; the
// default `mesh_sweep`, cloth/mesh_ccd/mesh_sweep.hpp, streams its candidates to the narrow
// phase in blocks of a fixed buffer per thread, so they are never all held; any other
// culler returns its candidates at once and they go to the narrow phase in blocks), and the
// narrow phase: the conservative kernel (cloth/ccd/triangle_ccd.hpp: no false negative), and
// with `exact` the GMP reference (cloth/exact/exact_ccd.hpp) on every kernel hit.
//
// Results do not depend on the thread count: collisions are sorted, counts are sums and
// the time of impact is a minimum.
#include <cloth/cull/candidate.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ccd::cloth {

struct MeshCcdOptions {
  double separation = 0.0;           ///< minimum separation, mesh units, >= 0, finite
  std::string culler = "mesh_sweep"; ///< any name find_culler() accepts
  unsigned threads = 0;              ///< 0: one per hardware core
  bool exact = false;                ///< decide every kernel hit with the exact reference
  bool keep_candidates = false;      ///< also return every candidate (sorted)
  /// Called from the calling thread as the broad and narrow phases advance: units of
  /// work done of total (chunks of the sweep, or blocks of candidates). May be empty.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

/// Earliest time of impact: the first contact of any colliding pair is >= `time`; and
/// `time + error` is a time by which some pair is certified within the separation (or
/// within the kernel's contact width: triangle_ccd.hpp, toi_upper). error is infinite when
/// no hit is certified at a time (a spent box budget).
struct MeshToi {
  double time = 0.0;
  double error = 0.0;
};

struct MeshCcdTimes {
  double boxes = 0.0;   ///< s: topology and swept boxes (mesh_sweep: sorted too)
  double broad = 0.0;   ///< s: broad phase
  double narrow = 0.0;  ///< s: narrow phase (kernel, and the exact reference)
};

struct MeshCcdResult {
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::uint64_t candidates_vf = 0, candidates_ee = 0;  ///< pairs passed to the kernel
  /// Colliding pairs, sorted: [vertex, face] and [a0, a1, b0, b1] (two edges by their
  /// vertex indices, a0 < a1, b0 < b1, edge a before edge b). The kernel's hits, or with
  /// `exact` the hits the exact reference confirms.
  std::vector<std::array<std::uint32_t, 2>> vf;
  std::vector<std::array<std::uint32_t, 4>> ee;
  /// With `exact`: the kernel's hits the exact reference refutes, sorted likewise.
  std::vector<std::array<std::uint32_t, 2>> false_vf;
  std::vector<std::array<std::uint32_t, 4>> false_ee;
  std::optional<MeshToi> toi;  ///< over the pairs reported in vf and ee; none without a collision
  std::uint64_t budget_spent = 0;  ///< kernel hits by a spent box budget (counted as contacts)
  MeshCcdTimes seconds;
  std::vector<Candidate> candidates;  ///< with keep_candidates, sorted
  std::vector<std::array<std::uint32_t, 2>> edge_list;  ///< the mesh's edges (index order of Candidate::a, b)
};

/// Throws std::invalid_argument naming the element ("frame 1: vertex 7: coordinate not
/// finite", "face 3: vertex index 9 out of range (8 vertices)", "unknown culler 'x'") on
/// bad input; the frames must have the same vertex count.
MeshCcdResult mesh_ccd(std::span<const Vec3> x0, std::span<const Vec3> x1,
                       std::span<const std::array<std::uint32_t, 3>> faces, const MeshCcdOptions& options = {});

}  // namespace ccd::cloth
