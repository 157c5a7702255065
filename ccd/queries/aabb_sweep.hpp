#pragma once
// Moving AABB vs moving AABB under linear motion (separating-axis sweep, Gomez; ccd-math
// §6): the time interval [t_first, t_last] within [0, h] during which the closed boxes
// a + va t and b + vb t overlap.
//
// Units: box corners in scene length units, velocities in length per unit time, h in
// time units (h = 1 for normalised time; with va, vb the displacements over the step).
// Method: in a's frame b moves with v = vb - va. Per axis the closed overlap interval is
//   v_i > 0: [(a.lo - b.hi) / v_i, (a.hi - b.lo) / v_i],
//   v_i < 0: [(a.hi - b.lo) / v_i, (a.lo - b.hi) / v_i],
//   v_i = 0: all t if the boxes overlap on axis i now, else EMPTY (no contact: the known
//            bug of the published code is to let that axis through);
// contact iff max(first) <= min(last) after clamping to [0, h]. Intervals are closed:
// boxes that only touch (at one instant, or sliding face to face) are in contact.
// Statuses: Overlapping (the boxes overlap or touch at t = 0: t_first = 0), Hit (first
//   contact at t_first in (0, h]), Miss (no contact in [0, h]: t_first = +inf,
//   t_last = -inf), Degenerate (h < 0 or NaN; h = +inf is allowed; a box with lo > hi, non-finite coordinates
//   or velocities: t_first = +inf, t_last = -inf).
// Guarantee: exact for the computed gaps and relative velocity (each difference is one
// rounding, the quotient another); no tolerance is applied, so the result is exact for
// inputs whose differences are representable (e.g. dyadic coordinates) and otherwise
// within those roundings. Not conservative beyond that.
#include <ccd/geometry/aabb.hpp>
#include <ccd/queries/query_status.hpp>

namespace ccd {

/// Hit, Overlapping, Miss or Degenerate (ccd/queries/query_status.hpp).
using AabbSweepStatus = QueryStatus;

struct AabbSweepResult {
  AabbSweepStatus status = AabbSweepStatus::Miss;
  double t_first = 0.0;  ///< first contact time in [0, h] (Hit, Overlapping), else +inf
  double t_last = 0.0;   ///< last contact time in [t_first, h] (Hit, Overlapping), else -inf
};

AabbSweepResult aabb_sweep(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb, double h = 1.0);

}  // namespace ccd
