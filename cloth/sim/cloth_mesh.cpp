#include "cloth_mesh.hpp"

#include <algorithm>

namespace ccd::cloth {

std::vector<Vec3> initial_positions(const ClothScene& s) {
  std::vector<Vec3> x(s.particle_count());
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) x[s.particle(i, j)] = s.origin + i * s.du + j * s.dv;
  return x;
}

ClothMesh make_grid_mesh(const ClothScene& s) {
  ClothMesh m;
  const std::vector<Vec3> x = initial_positions(s);
  auto spring = [&](std::uint32_t a, std::uint32_t b, SpringKind k) { m.springs.push_back({a, b, (x[b] - x[a]).norm(), k}); };
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const std::uint32_t p = s.particle(i, j);
      if (i + 1 < s.nx) spring(p, s.particle(i + 1, j), SpringKind::Structural);
      if (j + 1 < s.ny) spring(p, s.particle(i, j + 1), SpringKind::Structural);
      if (i + 1 < s.nx && j + 1 < s.ny) {
        spring(p, s.particle(i + 1, j + 1), SpringKind::Shear);
        spring(s.particle(i + 1, j), s.particle(i, j + 1), SpringKind::Shear);
        const std::uint32_t q = s.particle(i + 1, j), r = s.particle(i + 1, j + 1), u = s.particle(i, j + 1);
        m.triangles.push_back({p, q, r});
        m.triangles.push_back({p, r, u});
      }
      if (i + 2 < s.nx) spring(p, s.particle(i + 2, j), SpringKind::Bend);
      if (j + 2 < s.ny) spring(p, s.particle(i, j + 2), SpringKind::Bend);
    }
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a > b) std::swap(a, b);
      m.edges.push_back({a, b});
    }
  std::sort(m.edges.begin(), m.edges.end());
  m.edges.erase(std::unique(m.edges.begin(), m.edges.end()), m.edges.end());
  m.chart.resize(x.size());
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) m.chart[s.particle(i, j)] = {double(i), double(j)};
  return m;
}

}  // namespace ccd::cloth
