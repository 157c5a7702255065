#pragma once
// The work a command is about to do, estimated before any of it, and the one check that
// refuses absurd work up front unless --force is given (docs/formats.md, "Work estimates and `--force`").
// Every command that computes (run, truth, view, poses, cloth, cloth frames, cloth queries,
// ccd, import, mesh-frames; animate in scripts/animate.py, in the same words) states its
// work in its own unit (body-steps, certified pair tests, page entries, particle-steps,
// faces, frames, queries, bytes) against a limit of that unit; past the limit
// the command exits 2 with the estimate, naming what makes it large, before it allocates
// or writes anything.
#include <ccd/motion/rigid_motion.hpp>

#include <cstddef>
#include <string>

namespace ccdlab {

/// One estimate: `amount` of `unit`, with what it is made of (`detail`, in parentheses in
/// the message), against `limit`.
struct WorkEstimate {
  double amount = 0.0;
  double limit = 0.0;
  std::string unit;    ///< e.g. "body-steps"
  std::string detail;  ///< e.g. "1000 bodies, up to 1e+08 steps per job"
};

/// Three significant digits ("1.2e+13", "430").
std::string work_number(double x);

/// Throws ccd::InputError(file, field, "needs AMOUNT UNIT (DETAIL), above the limit LIMIT
/// without --force") when the amount is above the limit (or not a number) and `force` is
/// false; does nothing otherwise.
void check_work(const WorkEstimate& work, bool force, const std::string& file, const std::string& field);

/// Checks that `path` is a regular file (not a folder, a device such as /dev/zero, or a
/// pipe) of at most `max_bytes` bytes unless `force`; returns its size. Throws
/// ccd::InputError naming `path`.
double check_input_file(const std::string& path, double max_bytes, bool force);

/// The windows of pair_window_work and certified_pair_work.
inline constexpr std::size_t kEstimateWindows = 16;

/// The point tests of one bracket evaluation per candidate pair-window of a scene with
/// shapes: the horizon is cut into `windows` windows; in each, every pair whose swept boxes
/// overlap (enumerated along the axis where fewest overlap; past 4e6 such pairs in a
/// window, all of them are counted as deep at the largest cost, an upper bound) counts
/// (1 + turn_a + turn_b) x (points_a + points_b), where turn is the body's largest point
/// speed times the window's length over its enclosing radius (how far it turns and moves,
/// in radii) and points the size of its convex proxy (1 for a sphere, 2 for a capsule, 8
/// for a box, a hull's points): one distance bracket visits each point of both proxies,
/// and a pair that turns further needs more of them. `deep` holds the pairs whose shapes
/// overlap deeply for the whole window: their centres' swept boxes stay within r_a + r_b,
/// r the radius of the largest sphere about the centre inside the shape (bounded by the
/// proxy's six axis-aligned support planes; a box's smallest half extent); `near` the others. The narrow phase of `ccdlab run` makes about one such
/// test per candidate pair and step.
struct PairWork {
  double near = 0.0;
  double deep = 0.0;
};
PairWork pair_window_work(const ccd::RigidMotion& motion, std::size_t windows = kEstimateWindows);

/// The certified ground truth's bracket evaluations (ccd/truth/rigid_truth.hpp) per unit
/// of pair_window_work. Near: a pair that comes into contact in a window has its enter and
/// exit bracketed to 2^-30 of the horizon, about 30 halvings each. Deep (the shapes
/// turning inside each other all along): measured on piles of
/// spinning boxes at one point (every pair deep in every window), 1 thread, with
/// `ccdlab truth PILE.json --threads 1` (the pile of tests/cli/hostile_outputs_test.cpp)
/// on a shared 2-core machine under other builds (seconds, fastest first):
///   10 boxes (45 pairs):   23.7, 33.0, 55.4, 84.8;  deep pair_window_work 2.02e4
///   20 boxes (190 pairs):  98.0, 132.1, 181.6;      deep pair_window_work 8.49e4
///   40 boxes (780 pairs):  792.8;                   deep pair_window_work 3.5e5
/// the fastest runs take 1.15e-3 s per unit of deep work (the medians 1.5e-3 to 2.3e-3);
/// with 1e4 evaluations per unit, one certified pair test is about 1.2e-7 s (an evaluation
/// of two boxes, 16 points, about 2 us), so the limit 1e9 is about 2 minutes on one thread:
/// the 20-box pile is just under it (8.5e8), the 40-box pile above (3.5e9, 13 minutes here),
/// a pile of 300 boxes far above (2e11, hours). Every scene and experiment in data/ passes
/// (the most, wrap-crates.json, 2.2e8; its truth takes 3.7 s).
inline constexpr double kTruthEvaluationsNear = 64;
inline constexpr double kTruthEvaluationsDeep = 1e4;

/// The certified ground truth's work for a scene with shapes, in certified pair tests:
/// kTruthEvaluationsNear x near + kTruthEvaluationsDeep x deep (pair_window_work).
double certified_pair_work(const ccd::RigidMotion& motion, std::size_t windows = kEstimateWindows);
/// `ccdlab run`'s work on a scene with shapes, in certified pair tests: the truth's
/// (certified_pair_work, unless `truth_given`) and the narrow phase's, one test per
/// candidate pair at each of `steps` steps (summed over the jobs), a window's pairs at each
/// of its steps.
double run_pair_work(const ccd::RigidMotion& motion, double steps, bool truth_given);

/// The certified pair tests the truth and the rigid narrow phase accept without --force.
inline constexpr double kMaxPairWorkWithoutForce = 1e9;
/// What a certified pair test estimate is made of, for the refusal's message.
inline constexpr const char* kPairWorkDetail = "candidate pairs x bracket evaluations x hull points";

}  // namespace ccdlab
