#include <ccd/shape/convex_hull.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace ccd {
namespace {

struct Face {
  std::array<std::uint32_t, 3> v;
  Vec3 normal;    // (b - a) x (c - a), outward
  double offset;  // normal . a
  double length;  // |normal|
};

Face make_face(const std::vector<Vec3>& p, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  Face f{{a, b, c}, (p[b] - p[a]).cross(p[c] - p[a]), 0.0, 0.0};
  f.offset = f.normal.dot(p[a]);
  f.length = f.normal.norm();
  return f;
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

// The first tetrahedron: the point farthest from points[0], the one farthest from their
// line, the one farthest from their plane (as ccd::hull_degeneracy). Empty when degenerate.
std::vector<std::uint32_t> first_tetrahedron(const std::vector<Vec3>& p, double tol) {
  auto farthest = [&](auto dist) {
    std::uint32_t best = 0;
    double bd = -1.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (const double d = dist(p[i]); d > bd) bd = d, best = static_cast<std::uint32_t>(i);
    return std::pair{best, bd};
  };
  const Vec3 p0 = p[0];
  const auto [i1, d1] = farthest([&](const Vec3& x) { return (x - p0).norm(); });
  if (!(d1 > tol)) return {};
  const Vec3 u = (p[i1] - p0) / d1;
  const auto [i2, d2] = farthest([&](const Vec3& x) { return (x - p0 - u * u.dot(x - p0)).norm(); });
  if (!(d2 > tol)) return {};
  const Vec3 n = u.cross(p[i2] - p0).normalized();
  const auto [i3, d3] = farthest([&](const Vec3& x) { return std::fabs(n.dot(x - p0)); });
  if (!(d3 > tol)) return {};
  return {0, i1, i2, i3};
}

}  // namespace

std::vector<std::array<Vec3, 3>> convex_hull_triangles(const std::vector<Vec3>& p) {
  if (p.size() < 4) return {};
  double scale = 0.0;
  for (const Vec3& x : p) scale = std::max(scale, x.norm());
  const double tol = 1e-9 * scale;
  const std::vector<std::uint32_t> t = first_tetrahedron(p, tol);
  if (t.empty()) return {};
  const Vec3 inner = (p[t[0]] + p[t[1]] + p[t[2]] + p[t[3]]) / 4.0;

  std::vector<Face> faces;
  std::vector<std::uint32_t> active;                     // faces on the hull now
  std::unordered_map<std::uint64_t, std::uint32_t> edge;  // directed edge a -> b: its face
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Face f = make_face(p, a, b, c);
    if (f.normal.dot(inner) - f.offset > 0.0) f = make_face(p, a, c, b);  // outward (first tetrahedron)
    const auto k = static_cast<std::uint32_t>(faces.size());
    for (int e = 0; e < 3; ++e) edge[edge_key(f.v[e], f.v[(e + 1) % 3])] = k;
    faces.push_back(f);
    active.push_back(k);
  };
  add(t[0], t[1], t[2]);
  add(t[0], t[1], t[3]);
  add(t[0], t[2], t[3]);
  add(t[1], t[2], t[3]);

  std::vector<char> visible(faces.size(), 0);
  std::vector<std::uint32_t> seen, kept;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> horizon;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto pi = static_cast<std::uint32_t>(i);
    if (std::find(t.begin(), t.end(), pi) != t.end()) continue;
    seen.clear();
    for (const std::uint32_t f : active)
      if (faces[f].normal.dot(p[i]) - faces[f].offset > tol * faces[f].length) seen.push_back(f);
    if (seen.empty()) continue;  // inside, or on the surface within the tolerance
    visible.resize(faces.size(), 0);
    for (const std::uint32_t f : seen) visible[f] = 1;
    // The horizon: edges of seen faces whose other face is not seen, kept in their
    // direction so the new faces are outward too.
    horizon.clear();
    for (const std::uint32_t f : seen)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t a = faces[f].v[e], b = faces[f].v[(e + 1) % 3];
        const auto twin = edge.find(edge_key(b, a));
        if (twin == edge.end() || !visible[twin->second]) horizon.emplace_back(a, b);
      }
    for (const std::uint32_t f : seen)
      for (int e = 0; e < 3; ++e) {
        const auto it = edge.find(edge_key(faces[f].v[e], faces[f].v[(e + 1) % 3]));
        if (it != edge.end() && it->second == f) edge.erase(it);
      }
    kept.clear();
    for (const std::uint32_t f : active)
      if (!visible[f]) kept.push_back(f);
    active.swap(kept);
    for (const auto& [a, b] : horizon) {
      const auto k = static_cast<std::uint32_t>(faces.size());
      faces.push_back(make_face(p, a, b, pi));
      for (const std::uint64_t key : {edge_key(a, b), edge_key(b, pi), edge_key(pi, a)}) edge[key] = k;
      active.push_back(k);
    }
  }
  std::vector<std::array<Vec3, 3>> out;
  out.reserve(active.size());
  for (const std::uint32_t f : active) out.push_back({p[faces[f].v[0]], p[faces[f].v[1]], p[faces[f].v[2]]});
  return out;
}

}  // namespace ccd
