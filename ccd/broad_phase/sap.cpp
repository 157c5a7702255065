#include <ccd/broad_phase/sap.hpp>

#include <algorithm>
#include <numeric>

namespace ccd {

void SweepAndPrune::rebuild(std::span<const Aabb> boxes) {
  const std::size_t n = boxes.size();
  // Axis of largest variance of the box centres (Welford: no s2 - s^2/n cancellation).
  double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const double c = 0.5 * boxes[i].lo[a] + 0.5 * boxes[i].hi[a];
      const double d = c - mean[a];
      mean[a] += d / static_cast<double>(i + 1);
      m2[a] += d * (c - mean[a]);
    }
  }
  axis_ = 0;
  for (int a = 1; a < 3; ++a)
    if (m2[a] > m2[axis_]) axis_ = a;

  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  const int ax = axis_;
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
    const double la = boxes[a].lo[ax], lb = boxes[b].lo[ax];
    return la < lb || (la == lb && a < b);
  });
  start_.resize(n);
  for (std::size_t k = 0; k < n; ++k) start_[k] = boxes[order_[k]].lo[ax];
}

bool SweepAndPrune::insertion_sort(std::uint64_t budget) {
  std::uint64_t swaps = 0;
  const std::size_t n = start_.size();
  double* s = start_.data();
  std::uint32_t* o = order_.data();
  for (std::size_t k = 1; k < n; ++k) {
    const double x = s[k];
    if (!(x < s[k - 1])) continue;
    const std::uint32_t id = o[k];
    std::size_t j = k;
    do {
      s[j] = s[j - 1];
      o[j] = o[j - 1];
      --j;
    } while (j > 0 && x < s[j - 1]);
    s[j] = x;
    o[j] = id;
    swaps += k - j;
    if (swaps > budget) {
      stats_.swaps = swaps;
      return false;
    }
  }
  stats_.swaps = swaps;
  return true;
}

void SweepAndPrune::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  out.clear();
  stats_ = {};
  const std::size_t n = boxes.size();
  if (n != order_.size() || n == 0) {
    rebuild(boxes);
    stats_.rebuilt = true;
  } else {
    const int ax = axis_;
    for (std::size_t k = 0; k < n; ++k) start_[k] = boxes[order_[k]].lo[ax];
    if (!insertion_sort(options_.swaps_per_body * n + 64)) {
      const std::uint64_t swaps = stats_.swaps;
      rebuild(boxes);
      stats_.swaps = swaps;
      stats_.rebuilt = true;
    }
  }
  const int ax = axis_, a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
  end_.resize(n);
  cross_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Aabb& b = boxes[order_[k]];
    end_[k] = b.hi[ax];
    cross_[k] = {b.lo[a1], b.hi[a1], b.lo[a2], b.hi[a2]};
  }
  // Sweep: starts are sorted, so lo_i <= lo_j for j > i and the x-overlap of i and j is
  // exactly lo_j <= hi_i.
  const double* s = start_.data();
  const double* e = end_.data();
  const Cross* c = cross_.data();
  std::uint64_t tests = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double hi = e[i];
    const Cross ci = c[i];
    std::size_t j = i + 1;
    for (; j < n && s[j] <= hi; ++j) {
      const Cross& cj = c[j];
      if (ci.lo1 <= cj.hi1 && cj.lo1 <= ci.hi1 && ci.lo2 <= cj.hi2 && cj.lo2 <= ci.hi2) {
        const std::uint32_t a = order_[i], b = order_[j];
        out.push_back(a < b ? BodyPair{a, b} : BodyPair{b, a});
      }
    }
    tests += j - i - 1;
  }
  stats_.box_tests = tests;
}

}  // namespace ccd
