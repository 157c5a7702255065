#include "work_estimate.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <sys/stat.h>
#include <cstdio>
#include <vector>

namespace ccdlab {

std::string work_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

void check_work(const WorkEstimate& work, bool force, const std::string& file, const std::string& field) {
  if (force || work.amount <= work.limit) return;  // NaN: refused
  throw ccd::InputError(file, field,
                        "needs " + work_number(work.amount) + " " + work.unit +
                            (work.detail.empty() ? std::string() : " (" + work.detail + ")") + ", above the limit " +
                            work_number(work.limit) + " without --force");
}

double check_input_file(const std::string& path, double max_bytes, bool force) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw ccd::InputError(path, "", std::string("cannot be opened: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw ccd::InputError(path, "", "is a folder; give a file");
  if (!S_ISREG(st.st_mode))
    throw ccd::InputError(path, "", "is not a regular file (a device or a pipe); give a file");
  const auto bytes = static_cast<double>(st.st_size);
  check_work({bytes, max_bytes, "bytes of input", "the file's size"}, force, path, "");
  return bytes;
}

namespace {

// Per body in one window: its swept box along one axis and the two factors of its cost.
struct Interval {
  double lo, hi;
  double turn;    // largest point speed x window length / enclosing radius
  double points;  // size of the convex proxy
};

// Sum over the pairs (i < j) whose intervals overlap of (1 + t_i + t_j)(n_i + n_j)^2, and
// their count, in O(n log n): sorted by lo, the partners of i that come after it are a
// contiguous range (lo_j <= hi_i); the cost expands into products of one body's and the
// other's terms, summed over the range with prefix sums.
std::array<double, 2> overlapping_pairs(std::vector<Interval>& v) {
  std::sort(v.begin(), v.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  const std::size_t n = v.size();
  // Prefix sums of 1, n, n^2, t, t n, t n^2 over the sorted order.
  std::vector<std::array<double, 6>> prefix(n + 1, std::array<double, 6>{});
  for (std::size_t k = 0; k < n; ++k) {
    const double p = v[k].points, t = v[k].turn;
    const std::array<double, 6> term = {1.0, p, p * p, t, t * p, t * p * p};
    for (int c = 0; c < 6; ++c) prefix[k + 1][c] = prefix[k][c] + term[c];
  }
  double pairs = 0.0, cost = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto end = std::upper_bound(v.begin() + static_cast<std::ptrdiff_t>(i) + 1, v.end(), v[i].hi,
                                      [](double x, const Interval& b) { return x < b.lo; });
    const auto j1 = static_cast<std::size_t>(end - v.begin());
    if (j1 <= i + 1) continue;
    std::array<double, 6> s{};
    for (int c = 0; c < 6; ++c) s[c] = prefix[j1][c] - prefix[i + 1][c];
    const double a = 1.0 + v[i].turn, p = v[i].points;
    // (a + t_j)(p^2 + 2 p n_j + n_j^2)
    cost += a * (p * p * s[0] + 2.0 * p * s[1] + s[2]) + (p * p * s[3] + 2.0 * p * s[4] + s[5]);
    pairs += s[0];
  }
  return {pairs, cost};
}

}  // namespace

double certified_pair_work(const ccd::RigidMotion& motion, std::size_t windows) {
  const ccd::Trajectories& traj = motion.centres();
  const std::size_t n = motion.size();
  const double horizon = traj.horizon();
  double total = 0.0;
  std::vector<ccd::Aabb> boxes(n);
  std::vector<Interval> intervals(n);
  std::vector<double> turn(n), points(n);
  for (std::size_t i = 0; i < n; ++i) points[i] = static_cast<double>(motion.proxy(i).points.size());
  for (std::size_t w = 0; w < windows; ++w) {
    const double u0 = horizon * static_cast<double>(w) / static_cast<double>(windows);
    const double u1 = w + 1 == windows ? horizon : horizon * static_cast<double>(w + 1) / static_cast<double>(windows);
    for (std::size_t i = 0; i < n; ++i) {
      boxes[i] = traj.swept_bounds(i, u0, u1);
      const double radius = std::max(motion.enclosing_radius(i), 1e-300);
      turn[i] = motion.max_point_speed(i, u0, u1) * (u1 - u0) / radius;
    }
    std::array<double, 3> cost{}, count{};
    for (int axis = 0; axis < 3; ++axis) {
      for (std::size_t i = 0; i < n; ++i) intervals[i] = {boxes[i].lo[axis], boxes[i].hi[axis], turn[i], points[i]};
      const auto [pairs, c] = overlapping_pairs(intervals);
      count[static_cast<std::size_t>(axis)] = pairs;
      cost[static_cast<std::size_t>(axis)] = c;
    }
    const auto best = std::min_element(count.begin(), count.end()) - count.begin();
    total += cost[static_cast<std::size_t>(best)];
  }
  return total;
}

}  // namespace ccdlab
