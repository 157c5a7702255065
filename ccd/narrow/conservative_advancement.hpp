#pragma once
// The generic narrow-phase entry for any pair of convex shapes (ccd/narrow/narrow_table.hpp):
// conservative advancement (Mirtich) on the certified GJK distance
// (ccd/queries/convex_distance.hpp), over the rigid motion of the two bodies
// (NarrowInput::motion, ccd/motion/rigid_motion.hpp).
//
// Step query [t0, t1]: with mu = max_point_speed(a) + max_point_speed(b) over the step,
// the distance cannot shrink faster than mu. At a time t GJK certifies a gap of at least
// `lower` along a unit direction n from A to B; the advancement steps t by the larger of
// two lower bounds on the time that gap needs to close: lower / rate with rate the
// smaller of mu and the approach speed along n (n.v_A - n.v_B plus |n x omega| R per
// body), and, when each body keeps one spin over the rest of the step, the root of
// c0 s + c1 s^2 / 2 = lower with c0 from the posed shapes' supports along n x omega and
// c1 from how fast those supports can grow as the bodies turn (docs/rigid_bodies.md).
// Each distance is warm-started from the previous direction. Advancing from t0:
//  - past t1: Miss (certified: no contact in [t0, t1]);
//  - certified overlap at t0: Overlapping, toi = t0, toi_error 0;
//  - lower <= tolerance at t (touching within the tolerance, or closer): the first
//    contact is not before t. Then the bracket's far end is searched: probes at
//    t + h, h = tolerance / mu doubling, until the overlap is certified at some t_hi, and
//    t_hi is halved towards t while the overlap stays certified. Hit, toi = t,
//    toi_error = t_hi - t (the first contact lies in [toi, toi + toi_error]), or
//    toi_error = +infinity when no overlap is found in the step: a near miss within the
//    tolerance, reported (conservative) but flagged;
//  - after max_iterations advances without reaching either: Hit at the last t with
//    toi_error +infinity (conservative: never a miss it cannot certify).
// signed_distance: the certified upper bound on the distance at toi.
// Sample test: Overlapping when the distance at t0 is not certified positive (touching
// counts), else Miss.
// Guarantee: zero misses (every real first contact time is >= toi and inside the step
// when reported), for any shapes and spin, within the rounding allowance of
// convex_distance.
#include <ccd/narrow/contact_result.hpp>
#include <ccd/narrow/narrow_query.hpp>
#include <ccd/shape/convex_proxy.hpp>

#include <cstdint>

namespace ccd {

struct AdvancementOptions {
  static constexpr double default_tolerance = 1e-9;  ///< metres
  static constexpr int default_max_iterations = 100000;
  double tolerance = default_tolerance;
  int max_iterations = default_max_iterations;
};

/// The table's entry (default options).
ContactResult conservative_advancement(const NarrowInput& in, std::uint32_t a, std::uint32_t b);
ContactResult conservative_advancement(const NarrowInput& in, std::uint32_t a, std::uint32_t b,
                                       const AdvancementOptions& options, int* iterations = nullptr);

/// The same for `body` against a convex shape at rest with the identity pose at the origin
/// (a static polygon: polygon_proxy, ccd/scene/scenery.hpp): B's velocity and
/// spin are zero, mu = max_point_speed(body).
ContactResult conservative_advancement_fixed(const NarrowInput& in, std::uint32_t body, const ConvexProxy& fixed,
                                             const AdvancementOptions& options = {}, int* iterations = nullptr);

}  // namespace ccd
