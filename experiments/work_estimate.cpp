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
#include <limits>
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

// Per body in one window: its swept box, its centre's, and the two factors of its cost.
struct Swept {
  ccd::Aabb box;     // the enclosing sphere's
  ccd::Aabb centre;  // the centre's
  double inner;   // the largest sphere about the centre inside the shape, at most
  double turn;    // largest point speed x window length / enclosing radius
  double points;  // size of the convex proxy
};

// Past this many pairs overlapping on the window's best axis, the pairs are not
// enumerated: every one of them is counted as overlapping deeply (an upper bound).
constexpr double kMaxEnumeratedPairs = 4e6;

// The pairs whose boxes overlap along `axis`, counted in O(n log n) on a sorted copy.
double overlapping_on_axis(const std::vector<Swept>& v, int axis) {
  std::vector<std::pair<double, double>> iv(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) iv[i] = {v[i].box.lo[axis], v[i].box.hi[axis]};
  std::sort(iv.begin(), iv.end());
  double pairs = 0.0;
  for (std::size_t i = 0; i < iv.size(); ++i) {
    const auto end = std::upper_bound(iv.begin() + static_cast<std::ptrdiff_t>(i) + 1, iv.end(),
                                      std::pair{iv[i].second, std::numeric_limits<double>::infinity()});
    pairs += static_cast<double>(end - iv.begin()) - static_cast<double>(i) - 1.0;
  }
  return pairs;
}

// The largest distance between the two centres over the window (far corners of their boxes).
double farthest_centres(const Swept& a, const Swept& b) {
  ccd::Vec3 d;
  for (int k = 0; k < 3; ++k)
    d[k] = std::max(std::fabs(a.centre.hi[k] - b.centre.lo[k]), std::fabs(b.centre.hi[k] - a.centre.lo[k]));
  return d.norm();
}

// An upper bound on the radius of the largest sphere about the body's centre inside its
// shape: the nearest of the six axis-aligned support planes of its convex proxy (exact
// for a sphere, a capsule and a box).
double inner_radius(const ccd::ConvexProxy& proxy) {
  double inner = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
    for (const double sign : {-1.0, 1.0}) {
      double reach = -std::numeric_limits<double>::infinity();
      for (const ccd::Vec3& p : proxy.points) reach = std::max(reach, sign * p[k]);
      inner = std::min(inner, reach);
    }
  return std::max(0.0, inner) + proxy.radius;
}

// One window's pairs whose swept boxes overlap, each (1 + t_a + t_b)(n_a + n_b), split
// into those whose shapes overlap deeply for the whole window (their centres stay within
// the sum of their inner radii) and the others.
PairWork window_work(std::vector<Swept>& v) {
  PairWork w;
  std::array<double, 3> count{};
  for (int axis = 0; axis < 3; ++axis) count[static_cast<std::size_t>(axis)] = overlapping_on_axis(v, axis);
  const int best = static_cast<int>(std::min_element(count.begin(), count.end()) - count.begin());
  if (count[static_cast<std::size_t>(best)] > kMaxEnumeratedPairs) {
    // Too many to list: each as deep, at the largest cost of a pair.
    double turn = 0.0, points = 0.0;
    for (const Swept& s : v) turn = std::max(turn, s.turn), points = std::max(points, s.points);
    w.deep = count[static_cast<std::size_t>(best)] * (1.0 + 2.0 * turn) * 2.0 * points;
    return w;
  }
  std::sort(v.begin(), v.end(), [best](const Swept& a, const Swept& b) { return a.box.lo[best] < b.box.lo[best]; });
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size() && v[j].box.lo[best] <= v[i].box.hi[best]; ++j) {
      const Swept& a = v[i];
      const Swept& b = v[j];
      if (!a.box.overlaps(b.box)) continue;
      const double cost = (1.0 + a.turn + b.turn) * (a.points + b.points);
      (farthest_centres(a, b) <= a.inner + b.inner ? w.deep : w.near) += cost;
    }
  return w;
}

}  // namespace

PairWork pair_window_work(const ccd::RigidMotion& motion, std::size_t windows) {
  const ccd::Trajectories& traj = motion.centres();
  const std::size_t n = motion.size();
  const double horizon = traj.horizon();
  PairWork total;
  std::vector<Swept> swept(n);
  std::vector<double> points(n), inner(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ccd::ConvexProxy proxy = motion.proxy(i);
    points[i] = static_cast<double>(proxy.points.size());
    inner[i] = inner_radius(proxy);
  }
  for (std::size_t w = 0; w < windows; ++w) {
    const double u0 = horizon * static_cast<double>(w) / static_cast<double>(windows);
    const double u1 = w + 1 == windows ? horizon : horizon * static_cast<double>(w + 1) / static_cast<double>(windows);
    for (std::size_t i = 0; i < n; ++i) {
      Swept& s = swept[i];
      s.box = traj.swept_bounds(i, u0, u1);
      const double radius = motion.enclosing_radius(i);
      s.centre = s.box;
      for (int k = 0; k < 3; ++k) {
        s.centre.lo[k] += radius;
        s.centre.hi[k] = std::max(s.centre.lo[k], s.centre.hi[k] - radius);
      }
      s.inner = inner[i];
      s.turn = motion.max_point_speed(i, u0, u1) * (u1 - u0) / std::max(radius, 1e-300);
      s.points = points[i];
    }
    const PairWork ww = window_work(swept);
    total.near += ww.near;
    total.deep += ww.deep;
  }
  return total;
}

double certified_pair_work(const ccd::RigidMotion& motion, std::size_t windows) {
  const PairWork w = pair_window_work(motion, windows);
  return kTruthEvaluationsNear * w.near + kTruthEvaluationsDeep * w.deep;
}

double run_pair_work(const ccd::RigidMotion& motion, double steps, bool truth_given) {
  const PairWork w = pair_window_work(motion);
  const double narrow = (w.near + w.deep) * steps / static_cast<double>(kEstimateWindows);
  return narrow + (truth_given ? 0.0 : kTruthEvaluationsNear * w.near + kTruthEvaluationsDeep * w.deep);
}

}  // namespace ccdlab
