#include "query_export.hpp"

#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <stdexcept>

namespace ccd::cloth {

namespace {

std::array<std::uint32_t, 4> query_vertices(const ClothMesh& mesh, const Candidate& c) {
  if (c.kind == PrimitivePair::VertexFace) {
    const auto& t = mesh.triangles[c.b];
    return {c.a, t[0], t[1], t[2]};
  }
  return {mesh.edges[c.a][0], mesh.edges[c.a][1], mesh.edges[c.b][0], mesh.edges[c.b][1]};
}

// True when, on some axis, the boxes of the two primitives' swept points are further apart
// than `gap` (exactly: a - b rounds monotonically, so an exact difference <= gap never
// rounds above gap, a double). Under linear motion each primitive stays in its box.
bool boxes_apart(PrimitivePair kind, const LinearQuery& q, double gap) {
  const int split = kind == PrimitivePair::VertexFace ? 1 : 2;
  for (int axis = 0; axis < 3; ++axis) {
    double lo[2] = {q.x[0][axis], q.x[static_cast<std::size_t>(split)][axis]}, hi[2] = {lo[0], lo[1]};
    for (int i = 0; i < 8; ++i) {
      const int side = (i % 4) < split ? 0 : 1;
      lo[side] = std::min(lo[side], q.x[static_cast<std::size_t>(i)][axis]);
      hi[side] = std::max(hi[side], q.x[static_cast<std::size_t>(i)][axis]);
    }
    if (lo[1] - hi[0] > gap || lo[0] - hi[1] > gap) return true;
  }
  return false;
}

}  // namespace

QueryExport export_queries(const ClothMesh& mesh, std::span<const std::vector<Vec3>> frames, std::size_t first,
                           std::size_t end, const CullerEntry& culler, const QueryExportOptions& options) {
  if (!(first < end && end < frames.size())) throw std::invalid_argument("export_queries: bad step range");
  QueryExport out;
  const auto instance = culler.make();
  mpq_class hard_squared;
  if (options.hard_below) hard_squared = mpq_class(*options.hard_below) * mpq_class(*options.hard_below);
  TriangleCcdOptions kernel;
  kernel.separation = options.hard_below.value_or(0.0);
  for (std::size_t s = first; s < end; ++s) {
    const std::vector<Candidate> candidates = instance->cull(mesh, frames[s], frames[s + 1], options.cull_separation);
    out.candidates += candidates.size();
    std::vector<ExportedQuery> found(candidates.size());
    std::vector<char> keep(candidates.size(), 1);
    parallel_for(candidates.size(), options.threads, [&](std::size_t k, unsigned) {
      ExportedQuery& e = found[k];
      e.step = static_cast<std::uint32_t>(s);
      e.candidate = candidates[k];
      e.vertices = query_vertices(mesh, candidates[k]);
      e.query = candidate_query(mesh, candidates[k], frames[s], frames[s + 1]);
      if (options.hard_below) {
        // Apart boxes and the kernel's Miss prove the distance stays above hard_below; the
        // reference decides the rest.
        keep[k] = !boxes_apart(e.candidate.kind, e.query, *options.hard_below) &&
                  triangle_ccd(e.candidate.kind, e.query, kernel).status != QueryStatus::Miss &&
                  exact_contact(e.candidate.kind, to_rational(e.query), hard_squared);
        if (!keep[k]) return;
      }
      // Boxes apart (compared exactly) prove no contact; the reference decides the rest.
      e.hit = !boxes_apart(e.candidate.kind, e.query, 0.0) &&
              exact_contact(e.candidate.kind, to_rational(e.query), mpq_class(0));
    });
    for (std::size_t k = 0; k < found.size(); ++k)
      if (keep[k])
        (found[k].candidate.kind == PrimitivePair::VertexFace ? out.vertex_face : out.edge_edge)
            .push_back(found[k]);
  }
  return out;
}

}  // namespace ccd::cloth
