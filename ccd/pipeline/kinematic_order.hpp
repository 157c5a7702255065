#pragma once
// The kinematic principle (ray tracing's "skip the objects whose entry distance is beyond
// the closest hit already found") for one moving body against its static candidates in
// one step: the candidates are visited in order of their earliest possible contact (the
// bound's test_static `earliest`, a lower bound on the first contact time under the
// bound's assumption, as a ray's entry distance into an object's bounding volume is a
// lower bound on its hit distance); each is solved exactly; once a contact at time T is
// certain, every candidate whose earliest possible contact is later than T is skipped (it
// cannot be touched before T). The skipped candidates are the polygon tests saved.
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
      first = std::min(first, c.toi);
    }
  }
  return 0;
}

}  // namespace ccd
