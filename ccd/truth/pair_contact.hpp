#pragma once
// Exact contact intervals of one pair of bodies following their piecewise-quadratic
// trajectories (ccd/motion/trajectory.hpp): the narrow phase of the ground truth and of
// the experiment runner.
//
// The pieces of both bodies are walked together; on each common piece [c0, c1] (between
// consecutive breaks of either body: wall reflections and acceleration changes) both
// centres are evaluated at c0 and the contact set is solved exactly on the WHOLE common
// piece by ccd/queries/sphere_sphere_contact.hpp (quadratic when the pair shares its
// acceleration on the piece, quartic otherwise), then clipped to the requested [u0, u1].
// Because the piece, not the query window, fixes the expansion point and the root
// brackets, the same pair gives bit-identical times whatever window it is asked about.
//
// Units: the scene's (seconds). Contact: distance of centres <= r_a + r_b (closed).
// Intervals that meet at a break (contact continuing across it) are merged, as are
// intervals separated by no more than `merge_gap(horizon)` (16 ulps of the horizon:
// below the resolution of the times). A touching contact is an interval with
// enter == exit. Guarantee: exact up to the rounding band of sphere_sphere_contact.hpp.
// Degenerate cases: a == b, u1 < u0 or a body index out of range are the caller's error
// (checked by assertions only); an empty result means no contact in [u0, u1].
#include <ccd/motion/trajectory.hpp>
#include <ccd/queries/contact_interval.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace ccd {

/// Largest gap between two contact intervals of a pair that is still merged.
double merge_gap(double horizon);

/// Appends to `out` every maximal contact interval of bodies a and b within [u0, u1],
/// sorted by time (entries already in `out` are left alone).
void pair_contact_intervals(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double u0, double u1,
                            std::vector<ContactInterval>& out);

/// The first contact time of a and b in [u0, u1] (u0 itself when they are in contact at
/// u0), or nullopt. Equals the first `enter` of pair_contact_intervals on the same
/// window. Cheap: no allocation; only the common pieces up to the first contact are solved.
std::optional<double> pair_first_contact(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double u0,
                                         double u1);

}  // namespace ccd
