#pragma once
// Certified ground truth of a scene with rigid bodies (docs/truth.md, "Rigid bodies"):
// every contact interval of every pair, where contact means the closed shapes intersect.
//
// Per pair, the signed distance f(t) between the posed shapes is Lipschitz in time with
// constant L = max_point_speed(a) + max_point_speed(b) (ccd/motion/rigid_motion.hpp), and
// convex_distance (ccd/queries/convex_distance.hpp) brackets it at any instant. The
// bracket search labels [u0, u1]: at the midpoint m of a sub-interval, f(m) >= lower > 0
// certifies separation on (m - lower/L, m + lower/L), f(m) <= upper < 0 certifies overlap
// on (m - |upper|/L, m + |upper|/L); what is left is searched the same way, until pieces
// narrower than `time_tolerance` that neither side can claim, which stay unresolved.
// A separation certified only up to the distance band, max(L x time_tolerance, 1e-12 x
// (R_a + R_b)), does not count as separated (a sliding touch stays one event).
// A maximal run of pieces that are not certified separated is one event:
//  - with a certified overlap inside: enter lies between the run's start (certified
//    separation before it, or time 0) and the first certified overlap, exit between the
//    last certified overlap and the run's end; each is reported as the middle of its
//    bracket with enter_error / exit_error its half-width (0 at time 0 and at the horizon
//    when the overlap is certified there);
//  - with none: the pair's closest approach stays within the tolerance band. The event is
//    `grazing` (it may or may not exist), enter = exit = the run's middle, errors its
//    half-width; it is counted apart.
// A certified separation narrower than `time_tolerance` between two such runs does not
// split them: the search resolves crossings to about an ulp, and runs that close are one
// event (their brackets then hold both).
// Sphere x sphere pairs take the exact solver (ccd/truth/pair_contact.hpp; errors 0)
// unless `generic_spheres` asks for the bracket search (the cross-path test).
//
// The scene's truth is compute_truth (ccd/truth/truth.hpp): it finds the candidate runs
// (ccd/truth/truth_candidates.hpp) and calls the search below through the truth table
// (ccd/truth/truth_table.hpp) for every pair of kinds but sphere x sphere.
//
// A box that wraps around (ccd/scene/periodic.hpp): the images of every swept box that
// meet the cell join the sweep (a pair is a candidate when any two of its images' boxes
// overlap), and a run is searched per common trajectory piece (both centres in the cell on
// wrapped axes, no wrap inside) against every image shift of b whose centre box comes
// within the enclosing radii R_a + R_b of a's (at most one per axis, as for spheres: the
// edge is at least 4 x the largest enclosing radius); the events of all pieces and shifts
// are merged where their brackets meet (a contact that continues through the seam is one
// event). Orientation is not changed by a wrap.
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/truth_io.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ccd {

struct RigidTruthOptions {
  /// Seconds; 0: 2^-30 x horizon (about 1e-9 of it).
  double time_tolerance = 0.0;
  /// 0: one per hardware core.
  unsigned threads = 0;
  /// 0: automatic, as the sphere truth: ceil(0.5 x mean path extent / mean diameter), at
  /// most TruthOptions::max_auto_windows; else the count.
  std::size_t windows = 0;
  /// Solve sphere x sphere pairs by the bracket search too (cross-path tests).
  bool generic_spheres = false;
  /// Distance evaluations allowed per (pair, run); past it the rest is left unresolved.
  std::size_t max_evaluations = 1000000;
  /// When set and true, the pair windows not yet started are skipped (a cancelled run: the
  /// result is incomplete and is to be discarded). Null: never cancelled.
  const std::atomic<bool>* cancel = nullptr;
};

struct RigidTruthStats {
  std::size_t windows = 0;
  unsigned threads = 0;
  std::size_t candidate_runs = 0;
  std::size_t evaluations = 0;  ///< convex_distance calls
  std::size_t grazing = 0;      ///< events flagged grazing
  std::size_t pairs_in_contact = 0;
};

struct RigidTruthResult {
  std::vector<ContactEvent> events;  ///< sorted by (enter, a, b)
  std::vector<EventError> errors;    ///< one per event
  RigidTruthStats stats;
};

/// The bracket search of one pair in a scene that wraps around (motion.centres().periodic()): per common
/// trajectory piece in [u0, u1] and image shift of b that can bring the enclosing spheres
/// within contact, the bracket search with b's centre on that image; events merged where
/// their brackets meet (see the header comment). max_evaluations bounds the sum.
std::size_t periodic_pair_bracket_events(const RigidMotion& motion, std::uint32_t a, std::uint32_t b, double u0,
                                         double u1, double time_tolerance, std::size_t max_evaluations,
                                         std::vector<ContactEvent>& events, std::vector<EventError>& errors);

/// compute_truth (ccd/truth/truth.hpp) without scenery, with these options
/// (generic_spheres: bracket_truth_table()); errors has one entry per event.
RigidTruthResult compute_rigid_truth(const RigidMotion& motion, const RigidTruthOptions& options = {});

/// The bracket search of one pair on [u0, u1] (see the header comment); appends events
/// (a < b as given) and their errors. Returns the number of distance evaluations.
std::size_t pair_bracket_events(const RigidMotion& motion, std::uint32_t a, std::uint32_t b, double u0, double u1,
                                double time_tolerance, std::size_t max_evaluations, std::vector<ContactEvent>& events,
                                std::vector<EventError>& errors);

}  // namespace ccd
