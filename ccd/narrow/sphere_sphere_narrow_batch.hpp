#pragma once
// The sphere x sphere narrow phase for many pairs at once: out[i] is exactly
// sphere_sphere_narrow(in, pairs[i].a, pairs[i].b) (ccd/narrow/sphere_sphere_narrow.hpp),
// bit for bit, for step queries (in.sample false) on the exact motion.
//
// Pairs are gathered in blocks into a structure of arrays of relative motion at in.t0
// and classified by the certified SIMD filter of ccd/queries/sphere_pair_filter.hpp:
//   - certainly apart over [t0, t1]: Miss (the exact query's answer: see the filter);
//   - certainly in contact at t0: Overlapping at toi = t0, the signed distance from
//     sphere_signed_distance at t0 (the exact query's own shortcut, certain_contact,
//     answers Contact there too);
//   - anything else: the scalar exact query.
// A pair goes to the filter only when both bodies stay on one trajectory piece over the
// step (the piece that contains t0 starts strictly before t0, or is the body's first,
// and ends strictly after t1, or at t1 when it is the body's last), their accelerations are equal (so the relative motion is
// linear) and the scene is not periodic; every other pair (a wall reflection or an
// acceleration change inside the step, a step starting at a break, periodic images) is
// answered by the scalar query. The pieces are in.start_piece when given, else searched.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/narrow/contact_result.hpp>
#include <ccd/narrow/narrow_query.hpp>

#include <span>

namespace ccd {

/// out[i] = sphere_sphere_narrow(in, pairs[i].a, pairs[i].b) for every i (out.size() ==
/// pairs.size(), else std::invalid_argument). Sample tests (in.sample) are answered by the
/// scalar entry pair by pair.
void sphere_sphere_narrow_batch(const NarrowInput& in, std::span<const BodyPair> pairs, std::span<ContactResult> out);

}  // namespace ccd
