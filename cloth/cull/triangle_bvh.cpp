#include "triangle_bvh.hpp"

#include <cloth/cull/primitive_boxes.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ccd::cloth {

namespace {
constexpr double kAnyDirection = 4.0;  // > pi
}  // namespace

TriangleBvh::TriangleBvh(const ClothMesh& mesh, std::span<const Vec3> x) : mesh_(&mesh) {
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  triangle_edges_.resize(mesh.triangles.size());
  vertex_owner_.assign(x.size(), none);
  edge_owner_.assign(mesh.edges.size(), none);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = mesh.triangles[t][static_cast<std::size_t>(k)], b = mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
      if (vertex_owner_[a] == none) vertex_owner_[a] = static_cast<std::uint32_t>(t);
      if (a > b) std::swap(a, b);
      const std::array<std::uint32_t, 2> e{a, b};
      const auto it = std::lower_bound(mesh.edges.begin(), mesh.edges.end(), e);
      const auto edge = static_cast<std::uint32_t>(it - mesh.edges.begin());
      triangle_edges_[t][static_cast<std::size_t>(k)] = edge;
      if (edge_owner_[edge] == none) edge_owner_[edge] = static_cast<std::uint32_t>(t);
    }
  for (std::uint32_t v = 0; v < vertex_owner_.size(); ++v)
    if (vertex_owner_[v] == none) orphans_.push_back(v);
  // The chart's smallest altitude (2 area / edge length), rounded down by a relative 1e-12
  // (far above the dozen roundings of each altitude). A triangle that is not positively
  // oriented, or is a sliver whose area is not well above its rounding error, voids the chart.
  if (!mesh.chart.empty() && mesh.chart.size() == x.size() && !mesh.triangles.empty()) {
    double gap = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles) {
      const auto& p0 = mesh.chart[t[0]];
      const auto& p1 = mesh.chart[t[1]];
      const auto& p2 = mesh.chart[t[2]];
      const double e[3][2] = {{p1[0] - p0[0], p1[1] - p0[1]}, {p2[0] - p1[0], p2[1] - p1[1]}, {p0[0] - p2[0], p0[1] - p2[1]}};
      const double area2 = e[0][0] * (p2[1] - p0[1]) - e[0][1] * (p2[0] - p0[0]);
      double longest = 0;
      for (const auto& d : e) longest = std::max(longest, std::hypot(d[0], d[1]));
      if (!(area2 > 1e-6 * longest * longest) || !std::isfinite(area2)) {
        gap = 0;
        break;
      }
      gap = std::min(gap, area2 / longest);  // the smallest altitude is on the longest edge
    }
    chart_gap_ = gap * (1 - 1e-12);
  }
  owned_.resize(mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    Owned& o = owned_[t];
    for (std::uint32_t v : mesh.triangles[t])
      if (vertex_owner_[v] == t && (o.vertex_count == 0 || o.vertices[0] != v) && (o.vertex_count < 2 || o.vertices[1] != v))
        o.vertices[o.vertex_count++] = v;
    for (std::uint32_t e : triangle_edges_[t])
      if (edge_owner_[e] == t && (o.edge_count == 0 || o.edges[0] != e) && (o.edge_count < 2 || o.edges[1] != e))
        o.edges[o.edge_count++] = e;
  }
  rebuild(x);
}

void TriangleBvh::rebuild(std::span<const Vec3> x) {
  nodes_.clear();
  patches_.clear();
  root_ = -1;
  std::vector<std::uint32_t> tris(mesh_->triangles.size());
  for (std::uint32_t t = 0; t < tris.size(); ++t) tris[t] = t;
  nodes_.reserve(2 * tris.size());
  patches_.reserve(2 * tris.size());
  if (!tris.empty()) root_ = build(tris, 0, tris.size(), x);
  order_ = std::move(tris);
}

int TriangleBvh::build(std::vector<std::uint32_t>& tris, std::size_t begin, std::size_t end, std::span<const Vec3> x) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  patches_.push_back(Patch{});
  patches_[static_cast<std::size_t>(id)].begin = static_cast<std::uint32_t>(begin);
  patches_[static_cast<std::size_t>(id)].end = static_cast<std::uint32_t>(end);
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
  build(tris, begin, mid, x);  // the left child is node id + 1 (preorder)
  const int r = build(tris, mid, end, x);
  nodes_[static_cast<std::size_t>(id)].right = r;
  return id;
}

void TriangleBvh::refit(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate) {
  vertex_boxes(x0, x1, inflate, vertex_boxes_);
  separation_ = 2 * inflate;
  x0_.assign(x0.begin(), x0.end());
  x1_.assign(x1.begin(), x1.end());
  const std::span<const Aabb> vb(vertex_boxes_);
  edge_boxes_.resize(mesh_->edges.size());
  for (std::size_t e = 0; e < mesh_->edges.size(); ++e) edge_boxes_[e] = edge_box(vb, mesh_->edges[e]);
  triangle_boxes_.resize(mesh_->triangles.size());
  for (std::size_t t = 0; t < mesh_->triangles.size(); ++t) triangle_boxes_[t] = triangle_box(vb, mesh_->triangles[t]);
  cones_.resize(nodes_.size());
  if (root_ >= 0) refit_node(root_, x0, x1);
}

double TriangleBvh::quality() const {
  auto area = [](const Node& n) {
    const Vec3 e = n.hi - n.lo;
    return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
  };
  if (root_ < 0) return 1.0;
  double internal = 0;
  for (const Node& n : nodes_)
    if (n.triangle < 0) internal += area(n);
  const double root = area(nodes_[static_cast<std::size_t>(root_)]);
  return root > 0 ? internal / root : 1.0;
}

void TriangleBvh::refit_node(int n, std::span<const Vec3> x0, std::span<const Vec3> x1) {
  Node& node = nodes_[static_cast<std::size_t>(n)];
  Cone& cone = cones_[static_cast<std::size_t>(n)];
  if (node.triangle >= 0) {
    const auto& v = mesh_->triangles[static_cast<std::size_t>(node.triangle)];
    const Aabb& box = triangle_boxes_[static_cast<std::size_t>(node.triangle)];
    node.lo = box.lo;
    node.hi = box.hi;
    node.size = (node.hi - node.lo).norm();
    if (chart_gap_ > 0) {
      Patch& patch = patches_[static_cast<std::size_t>(n)];
      patch.count = 3;
      patch.su.setZero();
      patch.suu.setZero();
      patch.sx.setZero();
      patch.sxu.setZero();
      for (std::uint32_t vi : v) {
        const Eigen::Vector2d u(mesh_->chart[vi][0], mesh_->chart[vi][1]);
        const Vec3 xm = 0.5 * (x0[vi] + x1[vi]);
        patch.su += u;
        patch.suu += u * u.transpose();
        patch.sx += xm;
        patch.sxu += xm * u.transpose();
      }
    }
    // Bernstein coefficients of the normal over the interval.
    const Vec3 a0 = x0[v[1]] - x0[v[0]], b0 = x0[v[2]] - x0[v[0]];
    const Vec3 a1 = x1[v[1]] - x1[v[0]], b1 = x1[v[2]] - x1[v[0]];
    const Vec3 c[3] = {a0.cross(b0), 0.5 * (a0.cross(b1) + a1.cross(b0)), a1.cross(b1)};
    Vec3 unit[3];
    for (int k = 0; k < 3; ++k) {
      const double len = c[k].norm();
      if (!(len > 0) || !std::isfinite(len)) {
        cone.axis = Vec3::UnitZ();
        cone.half_angle = kAnyDirection;
        return;
      }
      unit[k] = c[k] / len;
    }
    const Vec3 sum = unit[0] + unit[1] + unit[2];
    const double sum_len = sum.norm();
    if (!(sum_len > 0)) {
      cone.axis = Vec3::UnitZ();
      cone.half_angle = kAnyDirection;
      return;
    }
    cone.axis = sum / sum_len;
    // One arc cosine per leaf (the cone's accuracy only steers culling: the flatness certificate
    // is the proof).
    const double lowest = std::min({cone.axis.dot(unit[0]), cone.axis.dot(unit[1]), cone.axis.dot(unit[2])});
    cone.half_angle = std::acos(std::clamp(lowest, -1.0, 1.0));
    return;
  }
  refit_node(n + 1, x0, x1);
  refit_node(node.right, x0, x1);
  const Node& l = nodes_[static_cast<std::size_t>(n + 1)];
  const Node& r = nodes_[static_cast<std::size_t>(node.right)];
  const Cone& lc = cones_[static_cast<std::size_t>(n + 1)];
  const Cone& rc = cones_[static_cast<std::size_t>(node.right)];
  node.lo = l.lo.cwiseMin(r.lo);
  node.hi = l.hi.cwiseMax(r.hi);
  if (chart_gap_ > 0) {
    Patch& patch = patches_[static_cast<std::size_t>(n)];
    const Patch& lp = patches_[static_cast<std::size_t>(n + 1)];
    const Patch& rp = patches_[static_cast<std::size_t>(node.right)];
    patch.count = lp.count + rp.count;
    patch.su = lp.su + rp.su;
    patch.suu = lp.suu + rp.suu;
    patch.sx = lp.sx + rp.sx;
    patch.sxu = lp.sxu + rp.sxu;
  }
  node.size = (node.hi - node.lo).norm();
  const Vec3 sum = lc.axis + rc.axis;
  if (lc.half_angle >= kAnyDirection || rc.half_angle >= kAnyDirection || !(sum.norm() > 1e-12)) {
    cone.axis = lc.axis;
    cone.half_angle = kAnyDirection;
    return;
  }
  cone.axis = sum.normalized();
  // The axis bisects the children's axes: it is as far from each.
  cone.half_angle = std::acos(std::clamp(cone.axis.dot(lc.axis), -1.0, 1.0)) + std::max(lc.half_angle, rc.half_angle);
}

std::vector<Candidate> TriangleBvh::self_candidates(bool use_cones, BvhStats* stats,
                                                    std::span<const std::uint8_t> active) const {
  std::vector<Candidate> out;
  out.reserve(last_count_ + last_count_ / 8);
  BvhStats s;
  Traversal tr{use_cones, active, {}, out, s};
  if (root_ >= 0) {
    if (!active.empty()) {
      tr.node_active.resize(nodes_.size());
      mark_active(root_, tr);
    }
    self(root_, tr);
    for (std::uint32_t v : orphans_)
      if (active.empty() || active[v]) orphan(v, root_, tr);
  }
  sort_candidates(out);  // unique already: each pair is emitted once
  if (stats) *stats = s;
  last_count_ = out.size();
  return out;
}

std::uint8_t TriangleBvh::mark_active(int n, Traversal& tr) const {
  const Node& node = nodes_[static_cast<std::size_t>(n)];
  std::uint8_t a = 0;
  if (node.triangle >= 0) {
    for (std::uint32_t v : mesh_->triangles[static_cast<std::size_t>(node.triangle)]) a |= tr.active[v] ? 1 : 0;
  } else {
    a = static_cast<std::uint8_t>(mark_active(n + 1, tr) | mark_active(node.right, tr));
  }
  return tr.node_active[static_cast<std::size_t>(n)] = a;
}

void TriangleBvh::self(int n, Traversal& tr) const {
  const Node& node = nodes_[static_cast<std::size_t>(n)];
  if (node.triangle >= 0) return;  // a triangle's own primitives are all adjacent
  if (!tr.node_active.empty() && !tr.node_active[static_cast<std::size_t>(n)]) return;
  if (tr.cones && cones_[static_cast<std::size_t>(n)].half_angle < std::numbers::pi / 2) {
    if (proved_apart(n)) {
      ++tr.stats.cone_culled;
      return;
    }
    ++tr.stats.cone_rejected;
  }
  self(n + 1, tr);
  self(node.right, tr);
  pair(n + 1, node.right, tr);
}

bool TriangleBvh::proved_apart(int index) const {
  const Patch& node = patches_[static_cast<std::size_t>(index)];
  if (!(chart_gap_ > 0) || node.count < 3) return false;
  // The affine fit P x ~ B u + c (least squares over the corners, mid-interval). Any B and c
  // give a valid certificate; the fit only makes it likely to succeed.
  const double n = node.count;
  const Eigen::Vector2d ubar = node.su / n;
  const Vec3 xbar = node.sx / n;
  const Eigen::Matrix2d cuu = node.suu / n - ubar * ubar.transpose();
  const Eigen::Matrix<double, 3, 2> cxu = node.sxu / n - xbar * ubar.transpose();
  const double det_uu = cuu.determinant();
  if (!(det_uu > 1e-12 * cuu.squaredNorm())) return false;
  // P: an orthonormal basis of the plane normal to the cone's axis.
  const Vec3 a = cones_[static_cast<std::size_t>(index)].axis;
  Vec3 e1 = std::abs(a.x()) < 0.9 ? Vec3::UnitX().cross(a) : Vec3::UnitY().cross(a);
  e1.normalize();
  const Vec3 e2 = a.cross(e1).normalized();
  Eigen::Matrix<double, 2, 3> P;
  P.row(0) = e1.transpose();
  P.row(1) = e2.transpose();
  const Eigen::Matrix2d B = P * cxu * cuu.inverse();
  const Eigen::Vector2d c = P * xbar - B * ubar;
  // sigma_min(B) = |det B| / sigma_max(B), sigma_max^2 = (F + sqrt(F^2 - 4 det^2)) / 2 with
  // F = |B|_F^2: sigma_max rounded up and the quotient down by a relative 1e-12 (far above
  // the dozen roundings).
  const double det = B.determinant(), f = B.squaredNorm();
  const double sigma_max = std::sqrt(0.5 * (f + std::sqrt(std::max(0.0, f * f - 4 * det * det)))) * (1 + 1e-12);
  const double sigma = std::abs(det) / sigma_max * (1 - 1e-12);
  if (!(sigma > 0) || !std::isfinite(sigma)) return false;
  const double budget = 0.5 * (sigma * chart_gap_ * (1 - 1e-12) - separation_ * (1 + 1e-12));
  if (!(budget > 0)) return false;
  // Residuals at both ends of the interval. A residual component is a dot product of 3 and
  // of 2 terms and one more subtraction: its rounding error is below 8 u times the sum of
  // the terms' magnitudes (u = 2^-53); 1e-13 times that sum is used.
  const double bmax = B.cwiseAbs().maxCoeff(), cmax = c.cwiseAbs().maxCoeff();
  for (std::uint32_t i = node.begin; i < node.end; ++i)
    for (std::uint32_t v : mesh_->triangles[order_[i]]) {
      const Eigen::Vector2d u(mesh_->chart[v][0], mesh_->chart[v][1]);
      const Eigen::Vector2d bu = B * u + c;
      const double umag = bmax * (std::abs(u.x()) + std::abs(u.y())) + cmax;
      for (const Vec3* x : {&x0_[v], &x1_[v]}) {
        const Eigen::Vector2d r = P * *x - bu;
        const double err = 1e-13 * (x->cwiseAbs().sum() + umag);
        if (r.norm() * (1 + 1e-15) + 2 * err > budget) return false;
      }
    }
  return true;
}

void TriangleBvh::pair(int a, int b, Traversal& tr) const {
  const Node& na = nodes_[static_cast<std::size_t>(a)];
  const Node& nb = nodes_[static_cast<std::size_t>(b)];
  if (!tr.node_active.empty() &&
      !(tr.node_active[static_cast<std::size_t>(a)] && tr.node_active[static_cast<std::size_t>(b)]))
    return;
  ++tr.stats.node_pairs;
  if ((na.lo.array() > nb.hi.array()).any() || (nb.lo.array() > na.hi.array()).any()) return;
  if (na.triangle >= 0 && nb.triangle >= 0) {
    ++tr.stats.leaf_pairs;
    emit(static_cast<std::uint32_t>(na.triangle), static_cast<std::uint32_t>(nb.triangle), tr);
    return;
  }
  if (nb.triangle >= 0 || (na.triangle < 0 && na.size >= nb.size)) {
    pair(a + 1, b, tr);
    pair(na.right, b, tr);
  } else {
    pair(a, b + 1, tr);
    pair(a, nb.right, tr);
  }
}

void TriangleBvh::orphan(std::uint32_t v, int n, Traversal& tr) const {
  const Node& node = nodes_[static_cast<std::size_t>(n)];
  if (!tr.node_active.empty() && !tr.node_active[static_cast<std::size_t>(n)]) return;
  ++tr.stats.node_pairs;
  const Aabb& vb = vertex_boxes_[v];
  if ((vb.lo.array() > node.hi.array()).any() || (node.lo.array() > vb.hi.array()).any()) return;
  if (node.triangle >= 0) {
    const Candidate c{PrimitivePair::VertexFace, v, static_cast<std::uint32_t>(node.triangle)};
    if (!adjacent(*mesh_, c)) tr.out.push_back(c);
    return;
  }
  orphan(v, n + 1, tr);
  orphan(v, node.right, tr);
}

void TriangleBvh::emit(std::uint32_t ta, std::uint32_t tb, Traversal& tr) const {
  const ClothMesh& m = *mesh_;
  const Aabb* vb = vertex_boxes_.data();
  const Aabb* eb = edge_boxes_.data();
  const bool all = tr.active.empty();
  auto active = [&](std::uint32_t v) { return all || tr.active[v] != 0; };
  auto vertex_face = [&](std::uint32_t from, std::uint32_t to) {
    const Owned& o = owned_[from];
    if (o.vertex_count == 0) return;
    const auto& face_vertices = m.triangles[to];
    if (!all && !active(face_vertices[0]) && !active(face_vertices[1]) && !active(face_vertices[2])) return;
    const Aabb& face = triangle_boxes_[to];
    for (int i = 0; i < o.vertex_count; ++i) {
      const std::uint32_t v = o.vertices[i];
      if (!active(v) || !vb[v].overlaps(face)) continue;
      if (v == face_vertices[0] || v == face_vertices[1] || v == face_vertices[2]) continue;  // adjacent
      tr.out.push_back(Candidate{PrimitivePair::VertexFace, v, to});
    }
  };
  vertex_face(ta, tb);
  vertex_face(tb, ta);
  const Owned& oa = owned_[ta];
  const Owned& ob = owned_[tb];
  for (int i = 0; i < oa.edge_count; ++i) {
    const std::uint32_t ea = oa.edges[i];
    const auto& va = m.edges[ea];
    if (!(active(va[0]) || active(va[1]))) continue;
    const Aabb& box_a = eb[ea];
    for (int j = 0; j < ob.edge_count; ++j) {
      const std::uint32_t e = ob.edges[j];
      const auto& ve = m.edges[e];
      if (!(active(ve[0]) || active(ve[1])) || !box_a.overlaps(eb[e])) continue;
      if (va[0] == ve[0] || va[0] == ve[1] || va[1] == ve[0] || va[1] == ve[1]) continue;  // adjacent
      tr.out.push_back(Candidate{PrimitivePair::EdgeEdge, std::min(ea, e), std::max(ea, e)});
    }
  }
}

void sort_candidates(std::vector<Candidate>& c) {
  // The order is (kind, a, b): a key packing the three fields in that order, each in the
  // bits its largest value needs, sorts the same. A least-significant-digit radix sort on
  // 11-bit digits sorts the keys in a few linear passes.
  auto width = [](std::uint64_t n) {
    int w = 0;
    while (w < 64 && (n >> w) != 0) ++w;
    return w;
  };
  std::uint32_t max_a = 0, max_b = 0;
  for (const Candidate& x : c) {
    max_a = std::max(max_a, x.a);
    max_b = std::max(max_b, x.b);
  }
  const int wa = width(max_a), wb = width(max_b);
  const int bits = wa + wb + 1;
  if (bits > 64 || c.size() < 256) {
    std::sort(c.begin(), c.end());
    return;
  }
  thread_local std::vector<std::uint64_t> keys, tmp;
  keys.resize(c.size());
  tmp.resize(c.size());
  for (std::size_t i = 0; i < c.size(); ++i)
    keys[i] = (static_cast<std::uint64_t>(c[i].kind) << (wa + wb)) | (static_cast<std::uint64_t>(c[i].a) << wb) | c[i].b;
  constexpr int kDigit = 11;
  for (int shift = 0; shift < bits; shift += kDigit) {
    std::size_t count[(1u << kDigit) + 1] = {};
    for (std::uint64_t k : keys) ++count[((k >> shift) & ((1u << kDigit) - 1)) + 1];
    for (std::size_t d = 1; d <= (1u << kDigit); ++d) count[d] += count[d - 1];
    for (std::uint64_t k : keys) tmp[count[(k >> shift) & ((1u << kDigit) - 1)]++] = k;
    keys.swap(tmp);
  }
  const std::uint64_t mask_b = (std::uint64_t{1} << wb) - 1, mask_a = (std::uint64_t{1} << wa) - 1;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const std::uint64_t k = keys[i];
    c[i] = Candidate{static_cast<PrimitivePair>(k >> (wa + wb)), static_cast<std::uint32_t>((k >> wb) & mask_a),
                     static_cast<std::uint32_t>(k & mask_b)};
  }
}

}  // namespace ccd::cloth
