#pragma once
// The contact events of body pairs (ContactEvent) and the sphere-only entry points of the
// ground truth. The truth of any scene is one call, compute_truth (ccd/truth/truth.hpp):
// candidates from ccd/truth/truth_candidates.hpp, each (pair, run of windows) solved by
// the entry of ccd/truth/truth_table.hpp for its shape kinds. For spheres that entry is
// pair_contact_intervals (ccd/truth/pair_contact.hpp), which solves each common
// trajectory piece whole, whatever the window: the result equals compute_truth_all_pairs
// bit for bit and does not depend on the thread or window count (docs/truth.md).
//
// Units: seconds. Touching contacts have enter == exit. Intervals that start before 0
// start at 0; those that run past the horizon end there.
#include <ccd/motion/trajectory.hpp>
#include <ccd/truth/truth_options.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ccd {

struct ContactEvent {
  std::uint32_t a = 0;  ///< body index, a < b
  std::uint32_t b = 0;
  double enter = 0.0;   ///< seconds, 0 <= enter <= exit <= horizon
  double exit = 0.0;
  bool operator==(const ContactEvent&) const = default;
};

/// Comparison used for the order of events: (enter, a, b).
bool event_order(const ContactEvent& x, const ContactEvent& y);

/// The truth of a scene of spheres without scenery: compute_truth (ccd/truth/truth.hpp)
/// of `traj` as a motion of balls, its events.
std::vector<ContactEvent> compute_truth(const Trajectories& traj, const TruthOptions& options = {});

/// Brute-force reference: pair_contact_intervals of all n(n-1)/2 pairs over the whole
/// horizon, sorted by (enter, a, b). For tests and small scenes only.
std::vector<ContactEvent> compute_truth_all_pairs(const Trajectories& traj);

}  // namespace ccd
