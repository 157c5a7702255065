#pragma once
// The kinematic principle (ray tracing's "skip the objects whose entry distance is beyond
// the closest hit already found") for one moving body against its static candidates in
// one step: the candidates are visited in order of their earliest possible contact (the
// bound's test_static `earliest`, a lower bound on the first contact time under the
// bound's assumption, as a ray's entry distance into an object's bounding volume is a
// lower bound on its hit distance); each is solved exactly; once a contact at time T is
// certain, every candidate whose earliest possible contact is later than T is skipped (it
// cannot be touched before T). The skipped candidates are the polygon tests saved. For a
// certified (not exact) solver, the contact is certain at toi + toi_error, the far end of
// its bracket: T is that, and a near miss with an infinite error never skips anything.
//
// Guarantee: the body's first contact in the step (the least toi over all candidates) is
// the same with and without skipping, for every conservative bound: a skipped candidate's
// contact, if any, starts after T. Contacts with other polygons later in the same step
// may go unreported, which is the point: a simulator stops the body at its first contact.
// Ties (earliest == T) are solved, so equal-time contacts are all reported.
#include <ccd/narrow/contact_result.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>

namespace ccd {

struct StaticCandidate {
  std::uint32_t polygon = 0;
  double earliest = 0.0;  ///< the bound's earliest possible contact with the polygon
};

/// Sorts `candidates` by (earliest, polygon) and visits them in that order: solve(polygon)
/// returns the exact ContactResult, found(polygon, result) receives every contact found.
/// Returns the number of candidates skipped (not solved).
template <class Solve, class Found>
std::size_t kinematic_visit(std::span<StaticCandidate> candidates, Solve&& solve, Found&& found) {
  std::sort(candidates.begin(), candidates.end(), [](const StaticCandidate& x, const StaticCandidate& y) {
    return x.earliest != y.earliest ? x.earliest < y.earliest : x.polygon < y.polygon;
  });
  double first = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].earliest > first) return candidates.size() - i;
    const ContactResult c = solve(candidates[i].polygon);
    if (c.found()) {
      found(candidates[i].polygon, c);
      // Certain by toi + toi_error (the bracket's far end; toi for an exact solver, never
      // for a near miss reported with an infinite error).
      first = std::min(first, c.toi + c.toi_error);
    }
  }
  return 0;
}

}  // namespace ccd
