#include "mesh_sweep.hpp"
#include <ccd/geometry/numeric_limits.hpp>

#include <cloth/cull/primitive_boxes.hpp>
#include <ccd/broad_phase/variance_axis.hpp>
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

// The slabs along the slab axis: slab(x) = clamp(floor((x - origin) / width), 0, count - 1),
// monotone in x as computed (a rounded difference and a rounded quotient by a positive
// number are monotone), so for boxes that overlap, slab(max(lo_a, lo_b)) = max(slab(lo_a),
// slab(lo_b)) lies in both boxes' slab ranges.
struct Slabs {
  double origin = 0.0, width = kInf;
  std::size_t count = 1;
  std::size_t of(double x) const {
    if (count == 1) return 0;
    const double q = (x - origin) / width;
    if (!(q > 0)) return 0;
    if (!(q < static_cast<double>(count))) return count - 1;
    return std::min(count - 1, static_cast<std::size_t>(q));
  }
};

constexpr std::size_t kMaxSlabs = std::size_t{1} << 16;

// Slabs of `width` from lo to hi: at most kMaxSlabs and at most `cap`; one slab when the
// width or the span is not > 0 and finite.
Slabs slabs_over(double lo, double hi, double width, std::size_t cap) {
  Slabs s;
  const double span = hi - lo;
  if (!(width > 0) || !std::isfinite(width) || !(span > 0) || !std::isfinite(span)) return s;
  const double most = static_cast<double>(std::max<std::size_t>(1, std::min(kMaxSlabs, cap)));
  const double wanted = std::ceil(span / width);
  s.origin = lo;
  if (!(wanted < most)) {
    s.count = static_cast<std::size_t>(most);
    s.width = span / most;
  } else {
    s.count = std::max<std::size_t>(1, static_cast<std::size_t>(wanted));
    s.width = width;
  }
  if (s.count == 1 || !(s.width > 0) || !std::isfinite(s.width)) s = Slabs{};
  return s;
}

struct Layout {
  int axis = 0, slab_axis = 1;
  Slabs slabs;
};

// The sweep axis, the slab axis and the slab width, chosen by the estimated cost of the
// edge-edge sweep (the largest of the three) on a sample of up to kSample edges spread over
// the mesh: for every sweep axis a, slab axis b != a and width (one slab, or 1, 2, 4, ...,
// 64 times the sample's median extent on b), the sample pairs whose a-intervals overlap
// times the slabs they share (the interval tests of the sweep), plus kEntryCost per box
// per slab it goes into, scaled to the whole mesh; the cheapest wins (ties: the first
// tried). Only speed depends on it: any layout gives the same candidates. With a given
// width: the axes of largest and second-largest variance of the vertex boxes' centres,
// that width.
constexpr std::size_t kSample = 512;
constexpr double kEntryCost = 16.0;

Layout choose_layout(std::span<const Aabb> vb, std::span<const std::array<std::uint32_t, 2>> edges, double width) {
  Layout best;
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  for (const Aabb& b : vb)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  if (width != 0 || edges.empty()) {
    best.axis = largest_variance_axis(vb);
    const int p = (best.axis + 1) % 3, q = (best.axis + 2) % 3;
    double mean[2] = {0, 0}, var[2] = {0, 0};
    for (const Aabb& b : vb) {
      mean[0] += 0.5 * b.lo[p] + 0.5 * b.hi[p];
      mean[1] += 0.5 * b.lo[q] + 0.5 * b.hi[q];
    }
    for (double& m : mean) m /= static_cast<double>(std::max<std::size_t>(1, vb.size()));
    for (const Aabb& b : vb) {
      const double dp = 0.5 * b.lo[p] + 0.5 * b.hi[p] - mean[0], dq = 0.5 * b.lo[q] + 0.5 * b.hi[q] - mean[1];
      var[0] += dp * dp;
      var[1] += dq * dq;
    }
    best.slab_axis = var[1] > var[0] ? q : p;
    if (var[1] == var[0]) best.slab_axis = std::min(p, q);
    if (!edges.empty()) best.slabs = slabs_over(lo[best.slab_axis], hi[best.slab_axis], width, vb.size());
    return best;
  }
  const std::size_t n = edges.size(), m = std::min(n, kSample);
  std::vector<Aabb> sample(m);
  for (std::size_t i = 0; i < m; ++i) {
    const auto& e = edges[i * n / m];
    sample[i] = vb[e[0]];
    sample[i].merge(vb[e[1]]);
  }
  const double pair_scale = m > 1 ? (static_cast<double>(n) * static_cast<double>(n - 1)) /
                                        (static_cast<double>(m) * static_cast<double>(m - 1))
                                  : 0.0;
  const double entry_scale = static_cast<double>(n) / static_cast<double>(m);
  double best_cost = kInf;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<std::size_t> first(m), last(m);
  std::vector<double> extent(m);
  for (int a = 0; a < 3; ++a) {
    pairs.clear();  // the sample pairs whose a-intervals overlap
    for (std::uint32_t i = 0; i < m; ++i)
      for (std::uint32_t j = i + 1; j < m; ++j)
        if (sample[i].lo[a] <= sample[j].hi[a] && sample[j].lo[a] <= sample[i].hi[a]) pairs.emplace_back(i, j);
    const double one_slab = static_cast<double>(pairs.size()) * pair_scale + kEntryCost * static_cast<double>(n);
    if (one_slab < best_cost) {
      best_cost = one_slab;
      best = Layout{a, (a + 1) % 3, Slabs{}};
    }
    for (int b = 0; b < 3; ++b) {
      if (b == a) continue;
      for (std::size_t i = 0; i < m; ++i) extent[i] = sample[i].hi[b] - sample[i].lo[b];
      std::nth_element(extent.begin(), extent.begin() + m / 2, extent.end());
      const double median = extent[m / 2];
      for (double factor = 1; factor <= 64; factor *= 2) {
        const Slabs slabs = slabs_over(lo[b], hi[b], factor * median, vb.size());
        if (slabs.count == 1) continue;
        double entries = 0;
        for (std::size_t i = 0; i < m; ++i) {
          first[i] = slabs.of(sample[i].lo[b]);
          last[i] = std::max(first[i], slabs.of(sample[i].hi[b]));
          entries += static_cast<double>(last[i] - first[i] + 1);
        }
        double tests = 0;
        for (const auto& [i, j] : pairs) {
          const std::size_t f = std::max(first[i], first[j]), l = std::min(last[i], last[j]);
          if (f <= l) tests += static_cast<double>(l - f + 1);
        }
        const double cost = tests * pair_scale + kEntryCost * entries * entry_scale;
        if (cost < best_cost) {
          best_cost = cost;
          best = Layout{a, b, slabs};
        }
      }
    }
  }
  return best;
}

// Puts every item of `items` (sorted) into the slabs its slab-axis interval overlaps:
// `out` holds the slabs' items concatenated, slab s at [offsets[s], offsets[s + 1]), each
// slab in the sorted order. Built in `parts` contiguous parts of `items` on the threads
// (the layout does not depend on them).
void place_in_slabs(const std::vector<Item>& items, const Slabs& slabs, unsigned threads,
                    std::vector<MeshSweep::SlabItem>& out, std::vector<std::size_t>& offsets) {
  const std::size_t n = items.size(), S = slabs.count;
  // At most 8 parts: each holds a count per slab.
  const std::size_t parts =
      std::max<std::size_t>(1, std::min<std::size_t>({threads, std::size_t{8}, (n + kBuildBlock - 1) / kBuildBlock}));
  std::vector<std::vector<std::size_t>> counts(parts, std::vector<std::size_t>(S + 1, 0));
  auto range = [&](std::size_t p) { return std::pair{n * p / parts, n * (p + 1) / parts}; };
  parallel_for(parts, threads, [&](std::size_t p, unsigned) {
    const auto [b, e] = range(p);
    auto& c = counts[p];
    for (std::size_t i = b; i < e; ++i) {
      const std::size_t first = slabs.of(items[i].lo1), last = std::max(first, slabs.of(items[i].hi1));
      for (std::size_t s = first; s <= last; ++s) ++c[s];
    }
  });
  offsets.assign(S + 1, 0);
  // cursor: counts[p][s] becomes where part p starts writing in slab s.
  std::size_t total = 0;
  for (std::size_t s = 0; s < S; ++s) {
    offsets[s] = total;
    for (std::size_t p = 0; p < parts; ++p) {
      const std::size_t c = counts[p][s];
      counts[p][s] = total;
      total += c;
    }
  }
  offsets[S] = total;
  out.resize(total);
  parallel_for(parts, threads, [&](std::size_t p, unsigned) {
    const auto [b, e] = range(p);
    auto& cursor = counts[p];
    for (std::size_t i = b; i < e; ++i) {
      const Item& it = items[i];
      const std::size_t first = slabs.of(it.lo1), last = std::max(first, slabs.of(it.hi1));
      const MeshSweep::SlabItem si{it.lo,  it.hi, it.lo1, it.hi1, it.lo2, it.hi2, it.id, static_cast<std::uint32_t>(first),
                                   static_cast<std::uint32_t>(i), it.v};
      for (std::size_t s = first; s <= last; ++s) out[cursor[s]++] = si;
    }
  });
}

// The slab holding position k of a set's concatenated slabs.
std::size_t slab_at(const std::vector<std::size_t>& offsets, std::size_t k) {
  return static_cast<std::size_t>(std::upper_bound(offsets.begin(), offsets.end(), k) - offsets.begin()) - 1;
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
    std::vector<Rec> a(n), b(n);
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

template <class A, class B>
inline bool overlap_others(const A& a, const B& b) {
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
  const Layout layout = choose_layout(vb.whole, mesh.edges, options.slab_width);
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
  const Slabs& slabs = layout.slabs;
  slabs_ = slabs.count;
  place_in_slabs(vertices_, slabs, threads, slab_vertices_, vertex_offsets_);
  place_in_slabs(faces_, slabs, threads, slab_faces_, face_offsets_);
  place_in_slabs(edges_, slabs, threads, slab_edges_, edge_offsets_);
  auto chunks_of = [](std::size_t n) { return (n + kChunk - 1) / kChunk; };
  edge_chunks_ = chunks_of(slab_edges_.size());
  face_chunks_ = chunks_of(slab_faces_.size());
  vertex_chunks_ = chunks_of(slab_vertices_.size());
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

// Slab entries [begin, end) of the faces against the vertices of the same slab whose
// start lies in [lo_f, hi_f] on the sweep axis (a vertex starting before the face is found
// from the vertex's side); a pair only in the slab max(first slabs).
void MeshSweep::sweep_faces(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const {
  Emitter out(buffer, sink);
  const SlabItem* v = slab_vertices_.data();
  std::size_t s = slab_at(face_offsets_, begin), next = face_offsets_[s + 1];
  std::size_t first = 0, last = 0;
  bool fresh = true;
  for (std::size_t k = begin; k < end; ++k) {
    while (k >= next) {
      next = face_offsets_[++s + 1];
      fresh = true;
    }
    const SlabItem& f = slab_faces_[k];
    if (fresh) {
      last = vertex_offsets_[s + 1];
      first = static_cast<std::size_t>(std::lower_bound(v + vertex_offsets_[s], v + last, f.lo,
                                                        [](const SlabItem& a, double x) { return a.lo < x; }) -
                                       v);
      fresh = false;
    }
    while (first < last && v[first].lo < f.lo) ++first;
    for (std::size_t j = first; j < last && v[j].lo <= f.hi; ++j) {
      if (std::max(f.first, v[j].first) != s || !overlap_others(f, v[j])) continue;
      const std::uint32_t id = v[j].id;
      if (id == f.v[0] || id == f.v[1] || id == f.v[2]) continue;
      if (time_halves_ && !halves_overlap(face_halves_[f.pos], vertex_halves_[v[j].pos])) continue;
      out.push({PrimitivePair::VertexFace, id, f.id});
    }
  }
  out.flush();
}

// Slab entries [begin, end) of the vertices against the faces of the same slab whose
// start lies in (lo_v, hi_v].
void MeshSweep::sweep_vertices(std::size_t begin, std::size_t end, std::span<Candidate> buffer,
                               const Sink& sink) const {
  Emitter out(buffer, sink);
  const SlabItem* f = slab_faces_.data();
  std::size_t s = slab_at(vertex_offsets_, begin), next = vertex_offsets_[s + 1];
  std::size_t first = 0, last = 0;
  bool fresh = true;
  for (std::size_t k = begin; k < end; ++k) {
    while (k >= next) {
      next = vertex_offsets_[++s + 1];
      fresh = true;
    }
    const SlabItem& v = slab_vertices_[k];
    if (fresh) {
      last = face_offsets_[s + 1];
      first = static_cast<std::size_t>(std::upper_bound(f + face_offsets_[s], f + last, v.lo,
                                                        [](double x, const SlabItem& a) { return x < a.lo; }) -
                                       f);
      fresh = false;
    }
    while (first < last && f[first].lo <= v.lo) ++first;
    for (std::size_t j = first; j < last && f[j].lo <= v.hi; ++j) {
      if (std::max(v.first, f[j].first) != s || !overlap_others(v, f[j])) continue;
      if (v.id == f[j].v[0] || v.id == f[j].v[1] || v.id == f[j].v[2]) continue;
      if (time_halves_ && !halves_overlap(vertex_halves_[v.pos], face_halves_[f[j].pos])) continue;
      out.push({PrimitivePair::VertexFace, v.id, f[j].id});
    }
  }
  out.flush();
}

// Slab entries [begin, end) of the edges against the following edges of the same slab
// starting before their end.
void MeshSweep::sweep_edges(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const {
  Emitter out(buffer, sink);
  const SlabItem* e = slab_edges_.data();
  std::size_t s = slab_at(edge_offsets_, begin), next = edge_offsets_[s + 1];
  for (std::size_t k = begin; k < end; ++k) {
    while (k >= next) next = edge_offsets_[++s + 1];
    const SlabItem& a = e[k];
    for (std::size_t j = k + 1; j < next && e[j].lo <= a.hi; ++j) {
      const SlabItem& b = e[j];
      if (std::max(a.first, b.first) != s || !overlap_others(a, b)) continue;
      if (a.v[0] == b.v[0] || a.v[0] == b.v[1] || a.v[1] == b.v[0] || a.v[1] == b.v[1]) continue;
      if (time_halves_ && !halves_overlap(edge_halves_[a.pos], edge_halves_[b.pos])) continue;
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
