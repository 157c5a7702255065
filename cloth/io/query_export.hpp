#pragma once
// Benchmark-format queries harvested from a cloth motion: every vertex-face and edge-edge
// candidate that a culler returns for the step intervals [first, end) (state s to state
// s + 1, linear per vertex), each with its exact answer at zero separation.
//
// The answer (the benchmark's 7th column) is exact: 0 when the boxes of the two primitives'
// swept points are apart on some axis (compared exactly), otherwise exact_contact at
// separation 0 on the query's doubles. The kernel is not used to decide it, so a file
// written here can check the kernel. With `hard_below = D`, only the queries whose two
// primitives come within distance D of each other (distance <= D, touching included) at
// some time of the step are kept: boxes further apart than D and the kernel at separation
// D remove pairs proved farther apart, and the exact reference at D^2 (D's double,
// squared exactly) decides the others.
#include <cloth/ccd/linear_query.hpp>
#include <cloth/cull/candidate.hpp>
#include <cloth/cull/cullers.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace ccd::cloth {

struct ExportedQuery {
  std::uint32_t step;                    ///< the interval from state step to step + 1
  Candidate candidate;                   ///< primitive ids: vertex and triangle, or two edges
  std::array<std::uint32_t, 4> vertices; ///< the mesh vertices of the query's four rows
  LinearQuery query;
  bool hit;                              ///< exact answer at separation 0
};

struct QueryExportOptions {
  double cull_separation = 0.0;        ///< m, >= 0: the separation the culler is run with
  std::optional<double> hard_below;    ///< m, >= 0: keep only queries within this distance
  unsigned threads = 1;                ///< for the exact reference (results do not depend on it)
};

struct QueryExport {
  std::vector<ExportedQuery> vertex_face, edge_edge;  ///< by step, then candidate order
  std::uint64_t candidates = 0;  ///< returned by the culler, before the hard_below filter
};

/// `frames[s]` is state s (one position per mesh vertex); requires first < end < frames.size().
/// One culler instance is kept over the steps (a refitted tree, as in a cloth run).
QueryExport export_queries(const ClothMesh& mesh, std::span<const std::vector<Vec3>> frames, std::size_t first,
                           std::size_t end, const CullerEntry& culler, const QueryExportOptions& options);

}  // namespace ccd::cloth
