#include "triangle_bvh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ccd::cloth {

namespace {
constexpr double kAnyDirection = 4.0;  // > pi

double angle_between(const Vec3& a, const Vec3& b) {  // a, b unit
  return std::atan2(a.cross(b).norm(), a.dot(b));
}
}  // namespace

TriangleBvh::TriangleBvh(const ClothMesh& mesh, std::span<const Vec3> x) : mesh_(&mesh) {
  triangle_edges_.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = mesh.triangles[t][static_cast<std::size_t>(k)], b = mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
      if (a > b) std::swap(a, b);
      const std::array<std::uint32_t, 2> e{a, b};
      const auto it = std::lower_bound(mesh.edges.begin(), mesh.edges.end(), e);
      triangle_edges_[t][static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(it - mesh.edges.begin());
    }
  std::vector<std::uint32_t> tris(mesh.triangles.size());
  for (std::uint32_t t = 0; t < tris.size(); ++t) tris[t] = t;
  nodes_.reserve(2 * tris.size());
  if (!tris.empty()) root_ = build(tris, 0, tris.size(), x);
}

int TriangleBvh::build(std::vector<std::uint32_t>& tris, std::size_t begin, std::size_t end, std::span<const Vec3> x) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  if (end - begin == 1) {
    nodes_[static_cast<std::size_t>(id)].triangle = static_cast<int>(tris[begin]);
    return id;
  }
  auto centroid = [&](std::uint32_t t) {
    const auto& v = mesh_->triangles[t];
    return Vec3((x[v[0]] + x[v[1]] + x[v[2]]) / 3.0);
  };
  Vec3 lo = centroid(tris[begin]), hi = lo;
  for (std::size_t i = begin; i < end; ++i) {
    lo = lo.cwiseMin(centroid(tris[i]));
    hi = hi.cwiseMax(centroid(tris[i]));
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const std::size_t mid = begin + (end - begin) / 2;
  std::nth_element(tris.begin() + static_cast<std::ptrdiff_t>(begin), tris.begin() + static_cast<std::ptrdiff_t>(mid),
                   tris.begin() + static_cast<std::ptrdiff_t>(end), [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = centroid(a)[axis], cb = centroid(b)[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const int l = build(tris, begin, mid, x);
  const int r = build(tris, mid, end, x);
  nodes_[static_cast<std::size_t>(id)].left = l;
  nodes_[static_cast<std::size_t>(id)].right = r;
  return id;
}

void TriangleBvh::refit(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate) {
  if (root_ >= 0) refit_node(root_, x0, x1, inflate);
}

void TriangleBvh::refit_node(int n, std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate) {
  Node& node = nodes_[static_cast<std::size_t>(n)];
  if (node.triangle >= 0) {
    const auto& v = mesh_->triangles[static_cast<std::size_t>(node.triangle)];
    node.lo = node.hi = x0[v[0]];
    for (std::uint32_t p : v) {
      node.lo = node.lo.cwiseMin(x0[p]).cwiseMin(x1[p]);
      node.hi = node.hi.cwiseMax(x0[p]).cwiseMax(x1[p]);
    }
    // Rounded outwards, so that the inflated box holds every point within `inflate`.
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      node.lo[k] = inflate > 0 ? std::nextafter(node.lo[k] - inflate, -inf) : node.lo[k];
      node.hi[k] = inflate > 0 ? std::nextafter(node.hi[k] + inflate, inf) : node.hi[k];
    }
    // Bernstein coefficients of the normal over the interval.
    const Vec3 a0 = x0[v[1]] - x0[v[0]], b0 = x0[v[2]] - x0[v[0]];
    const Vec3 a1 = x1[v[1]] - x1[v[0]], b1 = x1[v[2]] - x1[v[0]];
    const Vec3 c[3] = {a0.cross(b0), 0.5 * (a0.cross(b1) + a1.cross(b0)), a1.cross(b1)};
    Vec3 sum = Vec3::Zero();
    bool degenerate = false;
    for (const Vec3& n3 : c) {
      if (!(n3.norm() > 0)) degenerate = true;
      else sum += n3.normalized();
    }
    if (degenerate || !(sum.norm() > 0)) {
      node.axis = Vec3::UnitZ();
      node.half_angle = kAnyDirection;
      return;
    }
    node.axis = sum.normalized();
    node.half_angle = 0;
    for (const Vec3& n3 : c) node.half_angle = std::max(node.half_angle, angle_between(node.axis, n3.normalized()));
    return;
  }
  refit_node(node.left, x0, x1, inflate);
  refit_node(node.right, x0, x1, inflate);
  const Node& l = nodes_[static_cast<std::size_t>(node.left)];
  const Node& r = nodes_[static_cast<std::size_t>(node.right)];
  node.lo = l.lo.cwiseMin(r.lo);
  node.hi = l.hi.cwiseMax(r.hi);
  const Vec3 sum = l.axis + r.axis;
  if (l.half_angle >= kAnyDirection || r.half_angle >= kAnyDirection || !(sum.norm() > 1e-12)) {
    node.axis = l.axis;
    node.half_angle = kAnyDirection;
    return;
  }
  node.axis = sum.normalized();
  node.half_angle = std::max(angle_between(node.axis, l.axis) + l.half_angle, angle_between(node.axis, r.axis) + r.half_angle);
}

std::vector<Candidate> TriangleBvh::self_candidates(bool use_cones, BvhStats* stats) const {
  std::vector<Candidate> out;
  BvhStats s;
  if (root_ >= 0) self(root_, use_cones, out, s);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  if (stats) *stats = s;
  return out;
}

void TriangleBvh::self(int n, bool cones, std::vector<Candidate>& out, BvhStats& s) const {
  const Node& node = nodes_[static_cast<std::size_t>(n)];
  if (node.triangle >= 0) return;  // a triangle's own primitives are all adjacent
  if (cones && node.half_angle < std::numbers::pi / 2) {
    ++s.cone_culled;
    return;
  }
  self(node.left, cones, out, s);
  self(node.right, cones, out, s);
  pair(node.left, node.right, out, s);
}

void TriangleBvh::pair(int a, int b, std::vector<Candidate>& out, BvhStats& s) const {
  const Node& na = nodes_[static_cast<std::size_t>(a)];
  const Node& nb = nodes_[static_cast<std::size_t>(b)];
  ++s.node_pairs;
  if ((na.lo.array() > nb.hi.array()).any() || (nb.lo.array() > na.hi.array()).any()) return;
  if (na.triangle >= 0 && nb.triangle >= 0) {
    ++s.leaf_pairs;
    emit(static_cast<std::uint32_t>(na.triangle), static_cast<std::uint32_t>(nb.triangle), out);
    return;
  }
  if (nb.triangle >= 0 || (na.triangle < 0 && (na.hi - na.lo).norm() >= (nb.hi - nb.lo).norm())) {
    pair(na.left, b, out, s);
    pair(na.right, b, out, s);
  } else {
    pair(a, nb.left, out, s);
    pair(a, nb.right, out, s);
  }
}

void TriangleBvh::emit(std::uint32_t ta, std::uint32_t tb, std::vector<Candidate>& out) const {
  const ClothMesh& m = *mesh_;
  auto push = [&](Candidate c) {
    if (!adjacent(m, c)) out.push_back(c);
  };
  for (std::uint32_t v : m.triangles[ta]) push({PrimitivePair::VertexFace, v, tb});
  for (std::uint32_t v : m.triangles[tb]) push({PrimitivePair::VertexFace, v, ta});
  for (std::uint32_t ea : triangle_edges_[ta])
    for (std::uint32_t eb : triangle_edges_[tb]) {
      if (ea == eb) continue;
      push({PrimitivePair::EdgeEdge, std::min(ea, eb), std::max(ea, eb)});
    }
}

}  // namespace ccd::cloth
