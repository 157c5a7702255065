#include <bounds/rounding.hpp>
#include <bounds/swept_aabb_bound.hpp>

#include <stdexcept>

namespace ccd {

void SweptAabbBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  if (!ctx.exact) throw std::invalid_argument("swept_aabb needs the exact trajectories (StepContext::exact)");
  t0_ = ctx.t0;
  const std::size_t n = ctx.exact->size();
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Aabb box = ctx.exact->swept_bounds(i, ctx.t0, ctx.t1);
    const double slack = rounding_slack(box.lo.cwiseAbs().cwiseMax(box.hi.cwiseAbs()).maxCoeff());
    box.lo.array() -= slack;
    box.hi.array() += slack;
    boxes[i] = box;
  }
  boxes_.assign(boxes.begin(), boxes.end());
}

PairTest SweptAabbBound::test(std::uint32_t a, std::uint32_t b) const {
  if (!boxes_[a].overlaps(boxes_[b])) return PairTest::disjoint();
  return PairTest::possible_from(t0_);
}

}  // namespace ccd
