#pragma once
// What the narrow phase found for one pair over one step (or at one sample time).
#include <ccd/queries/query_status.hpp>

#include <limits>

namespace ccd {

struct ContactResult {
  /// Hit (first contact inside the step), Overlapping (in contact at its start, or at the
  /// sample time of a sample test), Miss, Degenerate or Failed.
  QueryStatus status = QueryStatus::Miss;
  /// Hit, Overlapping: the first contact time, seconds on the scene's clock. Else +infinity.
  double toi = std::numeric_limits<double>::infinity();
  /// Certified bound on |toi - exact first contact time| (seconds): 0 for the exact
  /// solvers; the bracket width for solvers that only bracket the time.
  double toi_error = 0.0;
  /// Hit, Overlapping: signed distance between the two surfaces at toi (length; negative
  /// = penetration depth). Spheres: |c_a - c_b| - (r_a + r_b). Else NaN.
  double signed_distance = std::numeric_limits<double>::quiet_NaN();

  bool found() const { return status == QueryStatus::Hit || status == QueryStatus::Overlapping; }
};

}  // namespace ccd
