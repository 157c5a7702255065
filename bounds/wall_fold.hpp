#pragma once
// Folding an interval of a freely moving coordinate into the walls (elastic reflection).
//
// A body in a wall box with elastic walls and |acceleration| <= A moves like a free body
// whose path is folded per axis: unfold each reflection by mirroring the rest of the path
// in the wall plane; the unfolded path is C1 with the same |acceleration| (a mirrored
// vector keeps its length), so it obeys every bound built for free motion, and the true
// centre coordinate is fold(unfolded) with fold the triangle wave of [L, H] (L = min + r,
// H = max - r). Reflections on different axes commute, so axes fold independently.
// Hence if a bound gives an interval [lo, hi] for the free centre coordinate, the true
// coordinate lies in fold([lo, hi]), which `fold_interval` encloses.
#include <algorithm>

namespace ccd {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

/// An interval containing fold([lo, hi]) into [L, H] (L <= H, lo <= hi): [lo, hi] itself
/// when inside; when it crosses H, [min(lo, 2H - hi), H] (the part beyond H mirrors back),
/// clipped at L (several folds stay in [L, H]); symmetric at L; [L, H] when it crosses both.
inline Interval fold_interval(double lo, double hi, double L, double H) {
  if (lo >= L && hi <= H) return {lo, hi};
  if (lo < L && hi > H) return {L, H};
  if (hi > H) return {std::max(L, std::min(lo, 2.0 * H - hi)), H};
  return {L, std::min(H, std::max(hi, 2.0 * L - lo))};
}

}  // namespace ccd
