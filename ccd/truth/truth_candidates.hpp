#pragma once
// The candidate finder of the ground truth (ccd/truth/truth.hpp): which (body, body) and
// (body, polygon) pairs may touch, and over which runs of time windows. Every kind of
// truth (exact sphere pairs, certified brackets, body-scenery) searches only these runs.
//
// The horizon is split into `windows` equal time windows. In each, body i's box is the
// exact box of its centre's path over the window (Piece::centre_bounds) grown by grow[i]
// (the caller's reach: the enclosing radius plus a rounding margin, truth_box_grow); a
// static polygon's box is its vertices' box. The boxes go into the columns of a uniform
// grid on the two axes of largest spread (cell size twice the mean box extent) and are
// swept along the third axis in each column; an overlapping pair is reported only by the
// column holding the low corner of the two boxes' overlap (so exactly once). Boxes that
// cover more than 64 columns (a floor polygon, a fast body) are checked against every box.
// In a scene that wraps around (ccd/scene/periodic.hpp), every image of a body's box that
// meets the cell joins the grid as a box of that body, so two bodies that can touch
// through an image shift are a candidate. Polygons are never paired with each other.
//
// The result is exactly the set of (pair, window) whose boxes overlap (closed boxes): the
// tests compare it with brute force. Consecutive windows of one pair are merged into one
// run. Windows are processed in parallel; the result does not depend on the thread count.
#include <ccd/geometry/aabb.hpp>
#include <ccd/motion/trajectory.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

/// One candidate: a pair over the consecutive windows [first_window, last_window].
struct CandidateRun {
  std::uint32_t a = 0;  ///< body
  std::uint32_t b = 0;  ///< body (a < b) or polygon index, by the list it is in
  std::uint32_t first_window = 0;
  std::uint32_t last_window = 0;
  bool operator==(const CandidateRun&) const = default;
};

struct TruthCandidates {
  std::size_t windows = 1;
  double horizon = 0.0;
  std::vector<CandidateRun> pairs;    ///< bodies a < b, sorted by (a, b, first_window)
  std::vector<CandidateRun> statics;  ///< (body, polygon), sorted by (a, b, first_window)
  std::size_t pair_windows = 0;       ///< (pair, window) box overlaps found
  std::size_t static_windows = 0;     ///< (body, polygon, window) box overlaps found
  /// Start of window k (k = windows gives the horizon exactly).
  double window_start(std::size_t k) const {
    return k == windows ? horizon : horizon * (static_cast<double>(k) / static_cast<double>(windows));
  }
};

/// The automatic window count: ceil(0.5 x mean path extent / mean diameter), at most
/// `max_windows` (a body's box grows by about two diameters per window; more windows cost
/// more box work than the few candidate pairs they save, measured on gas scenes).
std::size_t automatic_truth_windows(const Trajectories& traj, std::size_t max_windows);

/// How far body i's box reaches beyond its centre's path: its radius (the enclosing
/// radius of a shaped body) plus a margin that covers the rounding of positions evaluated
/// from different expansion points and the exact solvers' tangency band (1e-6 of the
/// body's coordinates, travel and radius: boxes a millionth larger cost nothing
/// measurable), and at least 1e-9 (1 + its coordinates and radius).
double truth_box_grow(const Trajectories& traj, std::size_t body);

/// The candidates of the scene (see the header comment). grow.size() == traj.size();
/// polygons: the static polygons' boxes (polygon_box, ccd/broad_phase/static_index.hpp),
/// empty without scenery; windows >= 1; threads 0: one per hardware core.
TruthCandidates find_truth_candidates(const Trajectories& traj, std::span<const double> grow,
                                      std::span<const Aabb> polygons, std::size_t windows, unsigned threads);

/// Body i's box in window [w0, w1] as find_truth_candidates builds it (for tests and
/// brute-force references).
Aabb truth_window_box(const Trajectories& traj, std::size_t body, double grow, double w0, double w1);

}  // namespace ccd
