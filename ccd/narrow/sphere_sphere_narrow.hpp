#pragma once
// The narrow-phase entry for sphere x sphere (ccd/narrow/narrow_table.hpp), exact:
//  - step query (in.sample false): the first contact in [t0, t1] of the pair's exact
//    piecewise-quadratic motion, ccd::pair_first_contact (ccd/truth/pair_contact.hpp):
//    Overlapping when in contact at t0, Hit at toi in (t0, t1], else Miss; toi_error 0
//    (exact up to the solver's rounding band, see sphere_sphere_contact.hpp);
//  - sample test (in.sample true): the two bodies touch at t0 by ccd::in_contact
//    (ccd/truth/contact_function.hpp), the ground truth's own and only definition of
//    touching: Overlapping with toi = t0, else Miss.
// signed_distance = |c_a - c_b| - (r_a + r_b) at toi: from the trajectories at toi
// (sphere_signed_distance), or from the start states for a sample test.
#include <ccd/narrow/contact_result.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/narrow/narrow_query.hpp>

#include <cstdint>

namespace ccd {

ContactResult sphere_sphere_narrow(const NarrowInput& in, std::uint32_t a, std::uint32_t b);

/// |c_a(t) - c_b(t)| - (r_a + r_b) on the trajectories (length; negative = penetration).
double sphere_signed_distance(const Trajectories& motion, std::uint32_t a, std::uint32_t b, double t);

}  // namespace ccd
