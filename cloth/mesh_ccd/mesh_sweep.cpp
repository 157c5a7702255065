#include "mesh_sweep.hpp"

#include <cloth/cull/primitive_boxes.hpp>
#include <ccd/broad_phase/variance_axis.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace ccd::cloth {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kBuildBlock = 8192;

using Item = MeshSweep::Item;
using Halves = MeshSweep::Halves;

struct VertexBoxes {
  std::vector<Aabb> whole, early, late;
};

void widen(Aabb& b, double inflate) {
  if (inflate > 0)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::nextafter(b.lo[k] - inflate, -kInf);
      b.hi[k] = std::nextafter(b.hi[k] + inflate, kInf);
    }
}

// The boxes of the vertices' paths over [0, 1], [0, 1/2] and [1/2, 1].
VertexBoxes vertex_box_sets(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate, bool halves,
                            unsigned threads) {
  const std::size_t n = x0.size();
  VertexBoxes out;
  out.whole.resize(n);
  if (halves) {
    out.early.resize(n);
    out.late.resize(n);
  }
  parallel_for((n + kBuildBlock - 1) / kBuildBlock, threads, [&](std::size_t block, unsigned) {
    const std::size_t end = std::min(n, (block + 1) * kBuildBlock);
    for (std::size_t i = block * kBuildBlock; i < end; ++i) {
      out.whole[i] = swept_point_box(x0[i], x1[i], inflate);
      if (!halves) continue;
      // 0.5 x0 + 0.5 x1 is within half a step of the exact midpoint (a step and a half in
      // the subnormal range): two steps either side hold it.
      const Vec3 mid = 0.5 * x0[i] + 0.5 * x1[i];
      Vec3 lo = mid, hi = mid;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::nextafter(std::nextafter(lo[k], -kInf), -kInf);
        hi[k] = std::nextafter(std::nextafter(hi[k], kInf), kInf);
      }
      out.early[i] = {x0[i].cwiseMin(lo), x0[i].cwiseMax(hi)};
      out.late[i] = {x1[i].cwiseMin(lo), x1[i].cwiseMax(hi)};
      widen(out.early[i], inflate);
      widen(out.late[i], inflate);
    }
  });
  return out;
}

template <std::size_t N>
Aabb union_box(std::span<const Aabb> boxes, const std::array<std::uint32_t, N>& v) {
  Aabb b = boxes[v[0]];
  for (std::size_t k = 1; k < N; ++k) b.merge(boxes[v[k]]);
  return b;
}

Item make_item(const Aabb& b, int ax, std::uint32_t id, std::array<std::uint32_t, 3> v) {
  const int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
  return {b.lo[ax], b.hi[ax], b.lo[a1], b.hi[a1], b.lo[a2], b.hi[a2], id, v};
}

Halves make_halves(const Aabb& early, const Aabb& late, int ax) {
  Halves h{};
  for (int k = 0; k < 3; ++k) {
    const int a = (ax + k) % 3;
    h.lo[0][k] = early.lo[a];
    h.hi[0][k] = early.hi[a];
    h.lo[1][k] = late.lo[a];
    h.hi[1][k] = late.hi[a];
  }
  return h;
}

// One set of primitives (vertices, faces or edges): the sort keys (start on the sweep
// axis, index), sorted, then the items and half-interval boxes built in sorted order.
struct PrimitiveSet {
  std::vector<std::pair<double, std::uint32_t>> keys;

  // lo(i): primitive i's start on the sweep axis.
  template <class Lo>
  void sort_keys(std::size_t count, unsigned threads, Lo&& lo) {
    keys.resize(count);
    parallel_for((count + kBuildBlock - 1) / kBuildBlock, threads, [&](std::size_t block, unsigned) {
      const std::size_t end = std::min(count, (block + 1) * kBuildBlock);
      for (std::size_t i = block * kBuildBlock; i < end; ++i) keys[i] = {lo(i), static_cast<std::uint32_t>(i)};
    });
  }
  void sort() { std::sort(keys.begin(), keys.end()); }
  // fill(i, item, halves or nullptr) builds primitive i.
  template <class Fill>
  void build(std::vector<Item>& items, std::vector<Halves>& halves, bool with_halves, unsigned threads,
             Fill&& fill) const {
    const std::size_t n = keys.size();
    items.resize(n);
    halves.resize(with_halves ? n : 0);
    parallel_for((n + kBuildBlock - 1) / kBuildBlock, threads, [&](std::size_t block, unsigned) {
      const std::size_t end = std::min(n, (block + 1) * kBuildBlock);
      for (std::size_t k = block * kBuildBlock; k < end; ++k)
        fill(keys[k].second, items[k], with_halves ? &halves[k] : nullptr);
    });
  }
};

// Fixed-size block of candidates handed to the sink when full.
class Emitter {
 public:
  Emitter(std::span<Candidate> buffer, const MeshSweep::Sink& sink) : buffer_(buffer), sink_(sink) {
    if (buffer.empty()) throw std::invalid_argument("mesh_sweep: empty candidate buffer");
  }
  void push(const Candidate& c) {
    buffer_[n_++] = c;
    if (n_ == buffer_.size()) flush();
  }
  void flush() {
    if (n_ != 0) sink_(std::span<const Candidate>(buffer_.data(), n_));
    n_ = 0;
  }

 private:
  std::span<Candidate> buffer_;
  const MeshSweep::Sink& sink_;
  std::size_t n_ = 0;
};

inline bool overlap_others(const Item& a, const Item& b) {
  return (a.lo1 <= b.hi1) & (b.lo1 <= a.hi1) & (a.lo2 <= b.hi2) & (b.lo2 <= a.hi2);
}

inline bool overlap_all(const Item& a, const Item& b) { return a.lo <= b.hi && b.lo <= a.hi && overlap_others(a, b); }

}  // namespace

void MeshSweep::prepare(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                        const MeshSweepOptions& options) {
  if (x0.size() != x1.size()) throw std::invalid_argument("mesh_sweep: x0 and x1 differ in size");
  if (!(options.separation >= 0) || !std::isfinite(options.separation))
    throw std::invalid_argument("mesh_sweep: the separation must be finite and >= 0");
  const unsigned threads = std::max(1u, options.threads);
  time_halves_ = options.time_halves;
  const VertexBoxes vb = vertex_box_sets(x0, x1, options.separation / 2, time_halves_, threads);
  axis_ = largest_variance_axis(vb.whole);
  const int ax = axis_;
  const bool h = time_halves_;

  PrimitiveSet sets[3];  // vertices, faces, edges
  sets[0].sort_keys(x0.size(), threads, [&](std::size_t i) { return vb.whole[i].lo[ax]; });
  sets[1].sort_keys(mesh.triangles.size(), threads, [&](std::size_t i) {
    const auto& t = mesh.triangles[i];
    return std::min({vb.whole[t[0]].lo[ax], vb.whole[t[1]].lo[ax], vb.whole[t[2]].lo[ax]});
  });
  sets[2].sort_keys(mesh.edges.size(), threads, [&](std::size_t i) {
    const auto& e = mesh.edges[i];
    return std::min(vb.whole[e[0]].lo[ax], vb.whole[e[1]].lo[ax]);
  });
  parallel_for(3, threads, [&](std::size_t s, unsigned) { sets[s].sort(); });
  sets[0].build(vertices_, vertex_halves_, h, threads, [&](std::uint32_t i, Item& item, Halves* halves) {
    item = make_item(vb.whole[i], ax, i, {i, i, i});
    if (halves) *halves = make_halves(vb.early[i], vb.late[i], ax);
  });
  sets[1].build(faces_, face_halves_, h, threads, [&](std::uint32_t i, Item& item, Halves* halves) {
    const auto& t = mesh.triangles[i];
    item = make_item(union_box<3>(vb.whole, t), ax, i, t);
    if (halves) *halves = make_halves(union_box<3>(vb.early, t), union_box<3>(vb.late, t), ax);
  });
  sets[2].build(edges_, edge_halves_, h, threads, [&](std::uint32_t i, Item& item, Halves* halves) {
    const auto& e = mesh.edges[i];
    item = make_item(union_box<2>(vb.whole, e), ax, i, {e[0], e[1], e[1]});
    if (halves) *halves = make_halves(union_box<2>(vb.early, e), union_box<2>(vb.late, e), ax);
  });
  auto chunks_of = [](std::size_t n) { return (n + kChunk - 1) / kChunk; };
  edge_chunks_ = chunks_of(edges_.size());
  face_chunks_ = chunks_of(faces_.size());
  vertex_chunks_ = chunks_of(vertices_.size());
}

bool MeshSweep::halves_overlap(const Halves& a, const Halves& b) const {
  for (int h = 0; h < 2; ++h) {
    bool all = true;
    for (int k = 0; k < 3; ++k) all &= (a.lo[h][k] <= b.hi[h][k]) & (b.lo[h][k] <= a.hi[h][k]);
    if (all) return true;
  }
  return false;
}

void MeshSweep::sweep(std::size_t chunk, std::span<Candidate> buffer, const Sink& sink) const {
  // Edge chunks first: they are the heaviest, and dynamic scheduling ends better with
  // the light ones last.
  if (chunk < edge_chunks_) {
    sweep_edges(chunk * kChunk, std::min(edges_.size(), (chunk + 1) * kChunk), buffer, sink);
    return;
  }
  chunk -= edge_chunks_;
  if (chunk < face_chunks_) {
    sweep_faces(chunk * kChunk, std::min(faces_.size(), (chunk + 1) * kChunk), buffer, sink);
    return;
  }
  chunk -= face_chunks_;
  if (chunk >= vertex_chunks_) throw std::out_of_range("mesh_sweep: no such chunk");
  sweep_vertices(chunk * kChunk, std::min(vertices_.size(), (chunk + 1) * kChunk), buffer, sink);
}

// Faces [begin, end) against the vertices whose start lies in [lo_f, hi_f] on the sweep
// axis (a vertex starting before the face is found from the vertex's side).
void MeshSweep::sweep_faces(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const {
  Emitter out(buffer, sink);
  const Item* v = vertices_.data();
  const std::size_t nv = vertices_.size();
  std::size_t first = static_cast<std::size_t>(
      std::lower_bound(vertices_.begin(), vertices_.end(), faces_[begin].lo,
                       [](const Item& a, double x) { return a.lo < x; }) -
      vertices_.begin());
  for (std::size_t k = begin; k < end; ++k) {
    const Item& f = faces_[k];
    while (first < nv && v[first].lo < f.lo) ++first;
    for (std::size_t j = first; j < nv && v[j].lo <= f.hi; ++j) {
      if (!overlap_others(f, v[j])) continue;
      const std::uint32_t id = v[j].id;
      if (id == f.v[0] || id == f.v[1] || id == f.v[2]) continue;
      if (time_halves_ && !halves_overlap(face_halves_[k], vertex_halves_[j])) continue;
      out.push({PrimitivePair::VertexFace, id, f.id});
    }
  }
  out.flush();
}

// Vertices [begin, end) against the faces whose start lies in (lo_v, hi_v].
void MeshSweep::sweep_vertices(std::size_t begin, std::size_t end, std::span<Candidate> buffer,
                               const Sink& sink) const {
  Emitter out(buffer, sink);
  const Item* f = faces_.data();
  const std::size_t nf = faces_.size();
  std::size_t first = static_cast<std::size_t>(
      std::upper_bound(faces_.begin(), faces_.end(), vertices_[begin].lo,
                       [](double x, const Item& a) { return x < a.lo; }) -
      faces_.begin());
  for (std::size_t k = begin; k < end; ++k) {
    const Item& v = vertices_[k];
    while (first < nf && f[first].lo <= v.lo) ++first;
    for (std::size_t j = first; j < nf && f[j].lo <= v.hi; ++j) {
      if (!overlap_others(v, f[j])) continue;
      if (v.id == f[j].v[0] || v.id == f[j].v[1] || v.id == f[j].v[2]) continue;
      if (time_halves_ && !halves_overlap(vertex_halves_[k], face_halves_[j])) continue;
      out.push({PrimitivePair::VertexFace, v.id, f[j].id});
    }
  }
  out.flush();
}

// Edges [begin, end) against the following edges starting before their end.
void MeshSweep::sweep_edges(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const {
  Emitter out(buffer, sink);
  const Item* e = edges_.data();
  const std::size_t ne = edges_.size();
  for (std::size_t k = begin; k < end; ++k) {
    const Item& a = e[k];
    for (std::size_t j = k + 1; j < ne && e[j].lo <= a.hi; ++j) {
      const Item& b = e[j];
      if (!overlap_others(a, b)) continue;
      if (a.v[0] == b.v[0] || a.v[0] == b.v[1] || a.v[1] == b.v[0] || a.v[1] == b.v[1]) continue;
      if (time_halves_ && !halves_overlap(edge_halves_[k], edge_halves_[j])) continue;
      out.push({PrimitivePair::EdgeEdge, std::min(a.id, b.id), std::max(a.id, b.id)});
    }
  }
  out.flush();
}

std::vector<Candidate> MeshSweep::all(unsigned threads) const {
  threads = std::max(1u, threads);
  std::vector<std::vector<Candidate>> found(threads);
  std::vector<std::vector<Candidate>> buffers(threads, std::vector<Candidate>(4096));
  parallel_for(chunks(), threads, [&](std::size_t k, unsigned w) {
    sweep(k, buffers[w], [&](std::span<const Candidate> block) {
      found[w].insert(found[w].end(), block.begin(), block.end());
    });
  });
  std::vector<Candidate> out;
  for (auto& f : found) out.insert(out.end(), f.begin(), f.end());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Candidate> MeshSweep::brute_force() const {
  std::vector<Candidate> out;
  auto halves_ok = [&](const Halves* a, const Halves* b) { return !time_halves_ || halves_overlap(*a, *b); };
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    for (std::size_t j = 0; j < faces_.size(); ++j) {
      const Item &v = vertices_[i], &f = faces_[j];
      if (v.id == f.v[0] || v.id == f.v[1] || v.id == f.v[2] || !overlap_all(v, f)) continue;
      if (halves_ok(time_halves_ ? &vertex_halves_[i] : nullptr, time_halves_ ? &face_halves_[j] : nullptr))
        out.push_back({PrimitivePair::VertexFace, v.id, f.id});
    }
  for (std::size_t i = 0; i < edges_.size(); ++i)
    for (std::size_t j = i + 1; j < edges_.size(); ++j) {
      const Item &a = edges_[i], &b = edges_[j];
      if (a.v[0] == b.v[0] || a.v[0] == b.v[1] || a.v[1] == b.v[0] || a.v[1] == b.v[1] || !overlap_all(a, b)) continue;
      if (halves_ok(time_halves_ ? &edge_halves_[i] : nullptr, time_halves_ ? &edge_halves_[j] : nullptr))
        out.push_back({PrimitivePair::EdgeEdge, std::min(a.id, b.id), std::max(a.id, b.id)});
    }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ccd::cloth
