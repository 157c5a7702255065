#pragma once
// The work a command is about to do, estimated before any of it, and the one check that
// refuses absurd work up front unless --force is given (docs/formats.md, "Work estimates and `--force`").
// Every command that computes (run, truth, view, poses, cloth, cloth frames, cloth queries,
// ccd, import) states its work in its own unit (body-steps, certified pair tests, page
// entries, particle-steps, queries, bytes) against a limit of that unit; past the limit
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

/// The windows of certified_pair_work.
inline constexpr std::size_t kEstimateWindows = 16;

/// The certified ground truth's work for a scene with shapes (ccd/truth/rigid_truth.hpp),
/// in pair tests: the horizon is cut into `windows` windows; in each, the pairs whose swept
/// boxes overlap along the axis where fewest do (an upper bound on the candidate pairs,
/// counted in O(n log n), never enumerated) each cost (1 + turn_a + turn_b) x (points_a +
/// points_b)^2, where turn is the body's largest point speed times the window's length over
/// its enclosing radius (how far it turns and moves, in radii) and points the size of its
/// convex proxy (1 for a sphere, 8 for a box, a hull's points). A pile of 1,000 spinning
/// boxes at one point is about 3e9, two 20,000-point hulls 3e10; 1e9 is minutes.
double certified_pair_work(const ccd::RigidMotion& motion, std::size_t windows = kEstimateWindows);
/// The certified pair tests the truth and the rigid narrow phase accept without --force.
inline constexpr double kMaxPairWorkWithoutForce = 1e9;

}  // namespace ccdlab
