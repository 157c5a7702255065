#include <ccd/queries/aabb_sweep.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <algorithm>
#include <limits>

namespace ccd {

AabbSweepResult aabb_sweep(const Aabb& a, const Vec3& va, const Aabb& b, const Vec3& vb, double h) {
  const AabbSweepResult none_degenerate{AabbSweepStatus::Degenerate, kInf, -kInf};
  const AabbSweepResult none_miss{AabbSweepStatus::Miss, kInf, -kInf};
  if (!(h >= 0.0)) return none_degenerate;  // h = +inf is allowed
  // Written so that NaN fails every test.
  if (!((a.lo.array() <= a.hi.array()).all() && (b.lo.array() <= b.hi.array()).all())) return none_degenerate;
  const Vec3 v = vb - va;
  if (!(v.allFinite() && a.lo.allFinite() && a.hi.allFinite() && b.lo.allFinite() && b.hi.allFinite())) {
    return none_degenerate;
  }

  double first = 0.0;
  double last = h;
  for (int i = 0; i < 3; ++i) {
    const double gap_lo = a.lo[i] - b.hi[i];  // b's hi must reach a's lo
    const double gap_hi = a.hi[i] - b.lo[i];  // b's lo must stay below a's hi
    if (v[i] == 0.0) {
      if (gap_lo > 0.0 || gap_hi < 0.0) return none_miss;  // separated on a still axis
      continue;
    }
    const double t0 = (v[i] > 0.0 ? gap_lo : gap_hi) / v[i];
    const double t1 = (v[i] > 0.0 ? gap_hi : gap_lo) / v[i];
    first = std::max(first, t0);
    last = std::min(last, t1);
  }
  if (!(first <= last)) return none_miss;
  return {first > 0.0 ? AabbSweepStatus::Hit : AabbSweepStatus::Overlapping, first, last};
}

}  // namespace ccd
