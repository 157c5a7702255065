#include <ccd/broad_phase/sort_sweep.hpp>
#include <ccd/broad_phase/variance_axis.hpp>

#include <algorithm>
#include <bit>
#include <numeric>

namespace ccd {

void SortAndSweep::rebuild(std::span<const Aabb> boxes) {
  const std::size_t n = boxes.size();
  axis_ = largest_variance_axis(boxes);  // Welford, robust far from the origin

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

bool SortAndSweep::insertion_sort(std::uint64_t budget) {
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
      swaps_ = swaps;
      return false;
    }
  }
  swaps_ = swaps;
  return true;
}

void SortAndSweep::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  out.clear();
  stats_ = {};
  swaps_ = 0;
  const std::size_t n = boxes.size();
  if (n != order_.size() || n == 0) {
    rebuild(boxes);
    stats_.rebuilt = true;
  } else {
    const int ax = axis_;
    for (std::size_t k = 0; k < n; ++k) start_[k] = boxes[order_[k]].lo[ax];
    if (!insertion_sort(options_.swaps_per_body * n + 64)) {
      const std::uint64_t swaps = swaps_;
      rebuild(boxes);
      swaps_ = swaps;
      stats_.rebuilt = true;
    }
  }
  const int ax = axis_, a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
  end_.resize(n);
  lo1_.resize(n);
  hi1_.resize(n);
  lo2_.resize(n);
  hi2_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Aabb& b = boxes[order_[k]];
    end_[k] = b.hi[ax];
    lo1_[k] = b.lo[a1];
    hi1_[k] = b.hi[a1];
    lo2_[k] = b.lo[a2];
    hi2_[k] = b.hi[a2];
  }
  // Sweep: starts are sorted, so lo_i <= lo_j for j > i and the x-overlap of i and j is
  // exactly lo_j <= hi_i. The candidates [i + 1, j_end) are then tested on the other two
  // axes 8 at a time without branches (a fixed-length loop the compiler vectorises),
  // branching only on the rare hits.
  const double* s = start_.data();
  const double* e = end_.data();
  const double* l1 = lo1_.data();
  const double* h1 = hi1_.data();
  const double* l2 = lo2_.data();
  const double* h2 = hi2_.data();
  const std::uint32_t* ord = order_.data();
  std::uint64_t tests = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double hi = e[i];
    std::size_t j_end = i + 1;
    while (j_end < n && s[j_end] <= hi) ++j_end;
    tests += j_end - i - 1;
    const double l1i = l1[i], h1i = h1[i], l2i = l2[i], h2i = h2[i];
    auto emit = [&](std::size_t j) {
      const std::uint32_t a = ord[i], b = ord[j];
      out.push_back(a < b ? BodyPair{a, b} : BodyPair{b, a});
    };
    std::size_t j = i + 1;
    for (; j + 8 <= j_end; j += 8) {
      unsigned mask = 0;
      for (unsigned t = 0; t < 8; ++t)
        mask |= static_cast<unsigned>((l1i <= h1[j + t]) & (l1[j + t] <= h1i) & (l2i <= h2[j + t]) &
                                      (l2[j + t] <= h2i))
                << t;
      while (mask != 0) {
        emit(j + static_cast<std::size_t>(std::countr_zero(mask)));
        mask &= mask - 1;
      }
    }
    for (; j < j_end; ++j)
      if ((l1i <= h1[j]) & (l1[j] <= h1i) & (l2i <= h2[j]) & (l2[j] <= h2i)) emit(j);
  }
  stats_.box_tests = tests;
  counters_[0].value = swaps_;
}

}  // namespace ccd
