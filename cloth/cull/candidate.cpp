#include "candidate.hpp"

namespace ccd::cloth {

bool adjacent(const ClothMesh& mesh, const Candidate& c) {
  if (c.kind == PrimitivePair::VertexFace) {
    const auto& t = mesh.triangles[c.b];
    return t[0] == c.a || t[1] == c.a || t[2] == c.a;
  }
  const auto& e = mesh.edges[c.a];
  const auto& f = mesh.edges[c.b];
  return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
}

std::vector<Candidate> brute_force_candidates(const ClothMesh& mesh, std::size_t vertex_count) {
  std::vector<Candidate> out;
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const Candidate c{PrimitivePair::VertexFace, v, t};
      if (!adjacent(mesh, c)) out.push_back(c);
    }
  for (std::uint32_t a = 0; a < mesh.edges.size(); ++a)
    for (std::uint32_t b = a + 1; b < mesh.edges.size(); ++b) {
      const Candidate c{PrimitivePair::EdgeEdge, a, b};
      if (!adjacent(mesh, c)) out.push_back(c);
    }
  return out;  // generated in sorted order
}

LinearQuery candidate_query(const ClothMesh& mesh, const Candidate& c, std::span<const Vec3> x0,
                            std::span<const Vec3> x1) {
  std::uint32_t p[4];
  if (c.kind == PrimitivePair::VertexFace) {
    const auto& t = mesh.triangles[c.b];
    p[0] = c.a;
    p[1] = t[0];
    p[2] = t[1];
    p[3] = t[2];
  } else {
    p[0] = mesh.edges[c.a][0];
    p[1] = mesh.edges[c.a][1];
    p[2] = mesh.edges[c.b][0];
    p[3] = mesh.edges[c.b][1];
  }
  LinearQuery q;
  for (int i = 0; i < 4; ++i) {
    q.x[static_cast<std::size_t>(i)] = x0[p[i]];
    q.x[static_cast<std::size_t>(i + 4)] = x1[p[i]];
  }
  return q;
}

}  // namespace ccd::cloth
