#include "mesh_sweep.hpp"
#include <ccd/geometry/numeric_limits.hpp>

#include <cloth/cull/primitive_boxes.hpp>
#include <cloth/mesh_ccd/sweep_layout.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

namespace ccd::cloth {

namespace {

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

// The box in the order (sweep axis ax, slab axis a1, the third axis).
Item make_item(const Aabb& b, int ax, int a1, std::uint32_t id, std::array<std::uint32_t, 3> v) {
  const int a2 = 3 - ax - a1;
  return {b.lo[ax], b.hi[ax], b.lo[a1], b.hi[a1], b.lo[a2], b.hi[a2], id, v};
}

// Puts every item of `items` (sorted) into the cells its two intervals across the sweep
// axis overlap: `out` holds the lists concatenated, list cell * 4 + class at
// [offsets[list], offsets[list + 1]), each list in the sorted order. The class of an item in
// a cell: bit 0 set when the cell is in the item's first slab on the slab axis, bit 1 on
// the third axis. Built in `parts` contiguous parts of `items` on the threads (the layout
// does not depend on them).
void place_in_cells(const DefaultInitVector<Item>& items, const SweepLayout& layout, unsigned threads,
                    DefaultInitVector<MeshSweep::SlabItem>& out, std::vector<std::size_t>& offsets) {
  const std::size_t n = items.size(), S2 = layout.slabs2.count, lists = 4 * layout.cells();
  // At most 8 parts: each holds a count per list.
  const std::size_t parts =
      std::max<std::size_t>(1, std::min<std::size_t>({threads, std::size_t{8}, (n + kBuildBlock - 1) / kBuildBlock}));
  std::vector<std::vector<std::size_t>> counts(parts, std::vector<std::size_t>(lists + 1, 0));
  auto range = [&](std::size_t p) { return std::pair{n * p / parts, n * (p + 1) / parts}; };
  // Each item's first and last slab on both axes.
  DefaultInitVector<std::array<std::uint32_t, 4>> spans(n);
  // f(list) for each list of item i.
  auto for_lists = [&](std::size_t i, auto&& f) {
    const auto [f1, l1, f2, l2] = spans[i];
    for (std::size_t s1 = f1; s1 <= l1; ++s1)
      for (std::size_t s2 = f2; s2 <= l2; ++s2) f(4 * (s1 * S2 + s2) + (s1 == f1 ? 1u : 0u) + (s2 == f2 ? 2u : 0u));
  };
  parallel_for(parts, threads, [&](std::size_t p, unsigned) {
    const auto [b, e] = range(p);
    auto& c = counts[p];
    for (std::size_t i = b; i < e; ++i) {
      const Item& it = items[i];
      const std::size_t f1 = layout.slabs.of(it.lo1), f2 = layout.slabs2.of(it.lo2);
      spans[i] = {static_cast<std::uint32_t>(f1), static_cast<std::uint32_t>(std::max(f1, layout.slabs.of(it.hi1))),
                  static_cast<std::uint32_t>(f2), static_cast<std::uint32_t>(std::max(f2, layout.slabs2.of(it.hi2)))};
      for_lists(i, [&](std::size_t list) { ++c[list]; });
    }
  });
  offsets.assign(lists + 1, 0);
  // cursor: counts[p][list] becomes where part p starts writing in that list.
  std::size_t total = 0;
  for (std::size_t l = 0; l < lists; ++l) {
    offsets[l] = total;
    for (std::size_t p = 0; p < parts; ++p) {
      const std::size_t c = counts[p][l];
      counts[p][l] = total;
      total += c;
    }
  }
  offsets[lists] = total;
  out.resize(total);
  parallel_for(parts, threads, [&](std::size_t p, unsigned) {
    const auto [b, e] = range(p);
    auto& cursor = counts[p];
    for (std::size_t i = b; i < e; ++i) {
      const Item& it = items[i];
      const MeshSweep::SlabItem si{it.lo, it.hi, it.lo1, it.hi1, it.lo2, it.hi2, it.id, static_cast<std::uint32_t>(i), it.v};
      for_lists(i, [&](std::size_t list) { out[cursor[list]++] = si; });
    }
  });
}

// The list holding position k of a set's concatenated lists.
std::size_t list_at(const std::vector<std::size_t>& offsets, std::size_t k) {
  return static_cast<std::size_t>(std::upper_bound(offsets.begin(), offsets.end(), k) - offsets.begin()) - 1;
}

// Entries [begin, end) of one set's lists (`own`, `own_offsets`) against the lists of the
// same cell in `other` whose class completes theirs (class | other class == 3: the pair's
// larger first slabs on both axes are this cell's, so it is met in this cell only): from
// the first entry b of each such list with !behind(a, b), while b starts on the sweep axis
// before a ends, visit(a, b). behind(a, b) must be monotone along a list (false after true
// never, true after false for a later a) and say which of the two meets the pair.
template <class Behind, class Visit>
void sweep_lists(const MeshSweep::SlabItem* own, const std::vector<std::size_t>& own_offsets, std::size_t begin,
                 std::size_t end, const MeshSweep::SlabItem* other, const std::vector<std::size_t>& other_offsets,
                 Behind&& behind, Visit&& visit) {
  std::size_t list = list_at(own_offsets, begin), next = own_offsets[list + 1];
  std::size_t at[4] = {}, stop[4] = {};
  unsigned with = 0;  // bit d: list d of the cell completes this class
  bool fresh = true;
  for (std::size_t k = begin; k < end; ++k) {
    while (k >= next) {
      next = own_offsets[++list + 1];
      fresh = true;
    }
    const MeshSweep::SlabItem& a = own[k];
    if (fresh) {
      const std::size_t cell = list / 4, cls = list % 4;
      with = 0;
      for (std::size_t d = 0; d < 4; ++d) {
        if ((cls | d) != 3) continue;
        const std::size_t first = other_offsets[4 * cell + d];
        stop[d] = other_offsets[4 * cell + d + 1];
        if (first == stop[d]) continue;
        with |= 1u << d;
        at[d] = static_cast<std::size_t>(
            std::partition_point(other + first, other + stop[d],
                                 [&](const MeshSweep::SlabItem& b) { return behind(a, b); }) - other);
      }
      fresh = false;
    }
    for (std::size_t d = 0; d < 4; ++d) {
      if (!(with >> d & 1)) continue;
      std::size_t j = at[d];
      while (j < stop[d] && behind(a, other[j])) ++j;
      at[d] = j;
      for (; j < stop[d] && other[j].lo <= a.hi; ++j) visit(a, other[j]);
    }
  }
}

Halves make_halves(const Aabb& early, const Aabb& late, int ax) {
  Halves h{};
  for (int k = 0; k < 3; ++k) {
    const int a = (ax + k) % 3;
    h.half[0].lo[k] = early.lo[a];
    h.half[0].hi[k] = early.hi[a];
    h.half[1].lo[k] = late.lo[a];
    h.half[1].hi[k] = late.hi[a];
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
  // The order of std::sort on (start, index) (starts are finite; -0 and +0 are equal), by
  // an LSD radix sort on the starts' bits made monotone, 16 bits a pass: stable, and the
  // keys come in index order (sort_keys), so equal starts stay in index order.
  void sort() {
    const std::size_t n = keys.size();
    if (n < 2) return;
    struct Rec {
      std::uint64_t bits;
      std::size_t pos;
    };
    DefaultInitVector<Rec> a(n), b(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = keys[i].first + 0.0;  // -0 -> +0
      std::uint64_t u;
      std::memcpy(&u, &x, sizeof u);
      u = (u >> 63) ? ~u : (u | (std::uint64_t{1} << 63));
      a[i] = {u, i};
    }
    std::vector<std::size_t> count(1 << 16);
    for (int shift = 0; shift < 64; shift += 16) {
      std::fill(count.begin(), count.end(), 0);
      for (const Rec& r : a) ++count[(r.bits >> shift) & 0xffff];
      if (count[(a[0].bits >> shift) & 0xffff] == n) continue;  // one digit: already in order
      std::size_t sum = 0;
      for (std::size_t& c : count) {
        const std::size_t k = c;
        c = sum;
        sum += k;
      }
      for (const Rec& r : a) b[count[(r.bits >> shift) & 0xffff]++] = r;
      a.swap(b);
    }
    const std::vector<std::pair<double, std::uint32_t>> in = keys;
    for (std::size_t i = 0; i < n; ++i) keys[i] = in[a[i].pos];
  }
  // fill(i, item, halves or nullptr) builds primitive i.
  template <class Fill>
  void build(DefaultInitVector<Item>& items, DefaultInitVector<Halves>& halves, bool with_halves, unsigned threads,
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

template <class A, class B>
inline bool overlap_others(const A& a, const B& b) {
  return (a.lo1 <= b.hi1) & (b.lo1 <= a.hi1) & (a.lo2 <= b.hi2) & (b.lo2 <= a.hi2);
}

inline bool overlap_all(const Item& a, const Item& b) { return a.lo <= b.hi && b.lo <= a.hi && overlap_others(a, b); }

// Whether the boxes over [0, 1/2] overlap, or those over [1/2, 1].
inline bool halves_overlap(const Halves& a, const Halves& b) {
  for (int h = 0; h < 2; ++h) {
    const Halves::Box &p = a.half[h], &q = b.half[h];
    if ((p.lo[0] <= q.hi[0]) & (q.lo[0] <= p.hi[0]) & (p.lo[1] <= q.hi[1]) & (q.lo[1] <= p.hi[1]) &
        (p.lo[2] <= q.hi[2]) & (q.lo[2] <= p.hi[2]))
      return true;
  }
  return false;
}

}  // namespace

void MeshSweep::prepare(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                        const MeshSweepOptions& options) {
  if (x0.size() != x1.size()) throw std::invalid_argument("mesh_sweep: x0 and x1 differ in size");
  if (!(options.separation >= 0) || !std::isfinite(options.separation))
    throw std::invalid_argument("mesh_sweep: the separation must be finite and >= 0");
  const unsigned threads = std::max(1u, options.threads);
  time_halves_ = options.time_halves;
  const VertexBoxes vb = vertex_box_sets(x0, x1, options.separation / 2, time_halves_, threads);
  const SweepLayout layout = choose_sweep_layout(vb.whole, mesh.edges, options.slab_width, options.slab_width2);
  axis_ = layout.axis;
  slab_axis_ = layout.slab_axis;
  const int ax = axis_, sa = slab_axis_;
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
    item = make_item(vb.whole[i], ax, sa, i, {i, i, i});
    if (halves) *halves = make_halves(vb.early[i], vb.late[i], ax);
  });
  sets[1].build(faces_, face_halves_, h, threads, [&](std::uint32_t i, Item& item, Halves* halves) {
    const auto& t = mesh.triangles[i];
    item = make_item(union_box<3>(vb.whole, t), ax, sa, i, t);
    if (halves) *halves = make_halves(union_box<3>(vb.early, t), union_box<3>(vb.late, t), ax);
  });
  sets[2].build(edges_, edge_halves_, h, threads, [&](std::uint32_t i, Item& item, Halves* halves) {
    const auto& e = mesh.edges[i];
    item = make_item(union_box<2>(vb.whole, e), ax, sa, i, {e[0], e[1], e[1]});
    if (halves) *halves = make_halves(union_box<2>(vb.early, e), union_box<2>(vb.late, e), ax);
  });
  slabs_ = layout.slabs.count;
  slabs2_ = layout.slabs2.count;
  place_in_cells(vertices_, layout, threads, slab_vertices_, vertex_offsets_);
  place_in_cells(faces_, layout, threads, slab_faces_, face_offsets_);
  place_in_cells(edges_, layout, threads, slab_edges_, edge_offsets_);
  auto chunks_of = [](std::size_t n) { return (n + kChunk - 1) / kChunk; };
  edge_chunks_ = chunks_of(slab_edges_.size());
  face_chunks_ = chunks_of(slab_faces_.size());
  vertex_chunks_ = chunks_of(slab_vertices_.size());
}


void MeshSweep::sweep(std::size_t chunk, std::span<Candidate> buffer, const Sink& sink) const {
  // Edge chunks first: they are the heaviest, and dynamic scheduling ends better with
  // the light ones last.
  if (chunk < edge_chunks_) {
    sweep_edges(chunk * kChunk, std::min(slab_edges_.size(), (chunk + 1) * kChunk), buffer, sink);
    return;
  }
  chunk -= edge_chunks_;
  if (chunk < face_chunks_) {
    sweep_faces(chunk * kChunk, std::min(slab_faces_.size(), (chunk + 1) * kChunk), buffer, sink);
    return;
  }
  chunk -= face_chunks_;
  if (chunk >= vertex_chunks_) throw std::out_of_range("mesh_sweep: no such chunk");
  sweep_vertices(chunk * kChunk, std::min(slab_vertices_.size(), (chunk + 1) * kChunk), buffer, sink);
}

// Entries [begin, end) of the faces' lists against the vertices of the same cell starting
// in [lo_f, hi_f] on the sweep axis (a vertex starting before the face is met from the
// vertex's side).
void MeshSweep::sweep_faces(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const {
  Emitter out(buffer, sink);
  sweep_lists(
      slab_faces_.data(), face_offsets_, begin, end, slab_vertices_.data(), vertex_offsets_,
      [](const SlabItem& f, const SlabItem& v) { return v.lo < f.lo; },
      [&](const SlabItem& f, const SlabItem& v) {
        if (!overlap_others(f, v) || v.id == f.v[0] || v.id == f.v[1] || v.id == f.v[2]) return;
        if (time_halves_ && !halves_overlap(face_halves_[f.pos], vertex_halves_[v.pos])) return;
        out.push({PrimitivePair::VertexFace, v.id, f.id});
      });
  out.flush();
}

// Entries [begin, end) of the vertices' lists against the faces of the same cell starting
// in (lo_v, hi_v].
void MeshSweep::sweep_vertices(std::size_t begin, std::size_t end, std::span<Candidate> buffer,
                               const Sink& sink) const {
  Emitter out(buffer, sink);
  sweep_lists(
      slab_vertices_.data(), vertex_offsets_, begin, end, slab_faces_.data(), face_offsets_,
      [](const SlabItem& v, const SlabItem& f) { return f.lo <= v.lo; },
      [&](const SlabItem& v, const SlabItem& f) {
        if (!overlap_others(v, f) || v.id == f.v[0] || v.id == f.v[1] || v.id == f.v[2]) return;
        if (time_halves_ && !halves_overlap(vertex_halves_[v.pos], face_halves_[f.pos])) return;
        out.push({PrimitivePair::VertexFace, v.id, f.id});
      });
  out.flush();
}

// Entries [begin, end) of the edges' lists against the edges of the same cell after them
// in the sorted order, starting before their end.
void MeshSweep::sweep_edges(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const {
  Emitter out(buffer, sink);
  sweep_lists(
      slab_edges_.data(), edge_offsets_, begin, end, slab_edges_.data(), edge_offsets_,
      [](const SlabItem& a, const SlabItem& b) { return b.pos <= a.pos; },
      [&](const SlabItem& a, const SlabItem& b) {
        if (!overlap_others(a, b)) return;
        if (a.v[0] == b.v[0] || a.v[0] == b.v[1] || a.v[1] == b.v[0] || a.v[1] == b.v[1]) return;
        if (time_halves_ && !halves_overlap(edge_halves_[a.pos], edge_halves_[b.pos])) return;
        out.push({PrimitivePair::EdgeEdge, std::min(a.id, b.id), std::max(a.id, b.id)});
      });
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
