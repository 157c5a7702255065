#pragma once
// The second look of the rigid ground truth at a pair with a ball (docs/truth.md,
// "Undecided events"): the bracket search (ccd/truth/bracket_search.hpp) with
// L = max_point_speed(a) + max_point_speed(b) can leave a long near pass unresolved (a
// plate spinning at 10 rad/s 5e-7 from a resting ball needs L / gap = 1.4e7 evaluations per
// second). Where one body s is a ball, the distance is that of s's centre from the other
// body h, seen in h's frame: with d = c_s - c_h and h's rotation R,
//
//   f(t) = dist(R^T d, core(h)) - r_h - r_s,    |f'| <= |v_s - v_h - omega_h x d|,
//
// so on a sub-interval [lo, hi] around m (omega_h constant there, |v_s - v_h| <= V):
//
//   |f'| <= V + |omega_h x d(m)| + |omega_h| V max(m - lo, hi - m),
//
// 0 for a ball resting on h's spin axis. This bound (rounded up; the constant one where it
// is smaller, or where h has a free spin) drives a search of the event's bracket alone,
// with no distance band, whose probe is the closed-form ball-box distance
// (ccd/queries/sphere_box_distance.hpp) when h is a box, convex_distance otherwise.
// Its events replace the grazing one: none (the gap is certified), certified contacts, or
// events that stay grazing and undecided.
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/truth/bracket_search.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ccd {

/// Re-searches [lo, hi] for the pair of ball `s` (kind Sphere) and body `h`; appends the
/// events found (errors as BracketSearch::events). `qs`, `qh`: the centres' pieces (a
/// periodic image's), or null for the trajectories'. Returns the distance evaluations.
std::size_t refine_sphere_pair(const RigidMotion& motion, std::uint32_t s, std::uint32_t h, double lo, double hi,
                               double time_tolerance, std::size_t max_evaluations, const Piece* qs, const Piece* qh,
                               std::vector<BracketEvent>& out);

}  // namespace ccd
