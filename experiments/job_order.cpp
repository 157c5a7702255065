#include "job_order.hpp"

#include <algorithm>
#include <numeric>

namespace ccdlab {

std::vector<std::size_t> job_order(std::span<const double> dt) {
  std::vector<std::size_t> order(dt.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return dt[x] < dt[y]; });
  return order;
}

}  // namespace ccdlab
