#include "sweep_layout.hpp"

#include <ccd/broad_phase/variance_axis.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ccd::cloth {

Slabs slabs_over(double lo, double hi, double width, std::size_t cap) {
  Slabs s;
  const double span = hi - lo;
  if (!(width > 0) || !std::isfinite(width) || !(span > 0) || !std::isfinite(span)) return s;
  const double most = static_cast<double>(std::max<std::size_t>(1, std::min(kMaxCells, cap)));
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

namespace {

// The sample: up to kSample edges spread over the mesh. The cost of a layout: the sample
// pairs the sweep tests (those whose sweep-axis intervals overlap and that share a cell:
// each is tested once, in the cell of its larger first slabs) plus kEntryCost per box per
// cell it goes into, scaled to the whole mesh. The options on each axis across the sweep:
// one slab, or 1, 2, 4, ..., 64 times the sample's median extent on it.
constexpr std::size_t kSample = 512;
constexpr double kEntryCost = 16.0;
constexpr int kOptions = 8;

struct Bounds {
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
};

Bounds bounds_of(std::span<const Aabb> vb) {
  Bounds r;
  for (const Aabb& b : vb)
    for (int k = 0; k < 3; ++k) {
      r.lo[k] = std::min(r.lo[k], b.lo[k]);
      r.hi[k] = std::max(r.hi[k], b.hi[k]);
    }
  return r;
}

// The axes of largest and second-largest variance of the boxes' centres, the given widths.
SweepLayout forced_layout(std::span<const Aabb> vb, const Bounds& range, bool any_edge, double width,
                          double width2) {
  SweepLayout best;
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
  if (!any_edge) return best;
  const int third = 3 - best.axis - best.slab_axis;
  best.slabs = slabs_over(range.lo[best.slab_axis], range.hi[best.slab_axis], width, vb.size());
  best.slabs2 = slabs_over(range.lo[third], range.hi[third], width2, vb.size() / best.slabs.count);
  return best;
}

// The options on axis b for the sample: their slabs, and each sample box's first and last
// slab under each.
struct AxisOptions {
  Slabs slabs[kOptions];
  std::vector<std::array<std::uint32_t, kOptions>> first, last;

  AxisOptions(const std::vector<Aabb>& sample, int b, const Bounds& range, std::size_t cap)
      : first(sample.size()), last(sample.size()) {
    const std::size_t m = sample.size();
    std::vector<double> extent(m);
    for (std::size_t i = 0; i < m; ++i) extent[i] = sample[i].hi[b] - sample[i].lo[b];
    std::nth_element(extent.begin(), extent.begin() + m / 2, extent.end());
    const double median = extent[m / 2];
    for (int o = 1; o < kOptions; ++o) slabs[o] = slabs_over(range.lo[b], range.hi[b], std::ldexp(median, o - 1), cap);
    for (std::size_t i = 0; i < m; ++i)
      for (int o = 0; o < kOptions; ++o) {
        const std::size_t f = slabs[o].of(sample[i].lo[b]);
        first[i][o] = static_cast<std::uint32_t>(f);
        last[i][o] = static_cast<std::uint32_t>(std::max(f, slabs[o].of(sample[i].hi[b])));
      }
  }
  // Whether option o is worth trying (the one slab, or more than one slab).
  bool valid(int o) const { return o == 0 || slabs[o].count > 1; }
  // Bit o: boxes i and j share a slab under option o.
  unsigned shared(std::size_t i, std::size_t j) const {
    unsigned mask = 0;
    for (int o = 0; o < kOptions; ++o)
      mask |= static_cast<unsigned>(std::max(first[i][o], first[j][o]) <= std::min(last[i][o], last[j][o])) << o;
    return mask;
  }
};

}  // namespace

SweepLayout choose_sweep_layout(std::span<const Aabb> vb, std::span<const std::array<std::uint32_t, 2>> edges,
                                double width, double width2) {
  const Bounds range = bounds_of(vb);
  if (width != 0 || edges.empty()) return forced_layout(vb, range, !edges.empty(), width, width2);
  const std::size_t cap = std::max<std::size_t>(1, std::min(kMaxCells, vb.size()));
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
  SweepLayout best;
  double best_cost = kInf;
  // histogram[(shared on b) << kOptions | (shared on c)]: sample pairs overlapping on a.
  std::vector<std::uint32_t> histogram(std::size_t{1} << (2 * kOptions));
  std::vector<std::uint32_t> touched;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const AxisOptions ob(sample, b, range, cap), oc(sample, c, range, cap);
    for (const std::uint32_t t : touched) histogram[t] = 0;
    touched.clear();
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 1; j < m; ++j)
        if (sample[i].lo[a] <= sample[j].hi[a] && sample[j].lo[a] <= sample[i].hi[a]) {
          const std::uint32_t t = ob.shared(i, j) << kOptions | oc.shared(i, j);
          if (histogram[t]++ == 0) touched.push_back(t);
        }
    for (int u = 0; u < kOptions; ++u) {
      if (!ob.valid(u)) continue;
      for (int v = 0; v < kOptions; ++v) {
        if (!oc.valid(v) || ob.slabs[u].count * oc.slabs[v].count > cap) continue;
        double tests = 0, entries = 0;
        for (const std::uint32_t t : touched)
          if ((t >> (kOptions + u) & 1) && (t >> v & 1)) tests += histogram[t];
        for (std::size_t i = 0; i < m; ++i)
          entries += static_cast<double>(ob.last[i][u] - ob.first[i][u] + 1) *
                     static_cast<double>(oc.last[i][v] - oc.first[i][v] + 1);
        const double cost = tests * pair_scale + kEntryCost * entries * entry_scale;
        if (cost < best_cost) {
          best_cost = cost;
          best = SweepLayout{a, b, ob.slabs[u], oc.slabs[v]};
          if (best.slabs.count == 1 && best.slabs2.count > 1) {  // slabs on c only: c is the slab axis
            best.slab_axis = c;
            std::swap(best.slabs, best.slabs2);
          }
        }
      }
    }
  }
  return best;
}

}  // namespace ccd::cloth
