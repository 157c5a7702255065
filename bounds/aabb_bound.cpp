#include <bounds/aabb_bound.hpp>
#include <bounds/rounding.hpp>

namespace ccd {

void AabbBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  t0_ = ctx.t0;
  const std::size_t n = ctx.start.size();
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState& s = ctx.start[i];
    boxes[i] = Aabb::around(s.position, s.radius + rounding_slack(s.position.cwiseAbs().maxCoeff() + s.radius));
  }
  boxes_.assign(boxes.begin(), boxes.end());
}

PairTest AabbBound::test(std::uint32_t a, std::uint32_t b) const {
  if (!boxes_[a].overlaps(boxes_[b])) return PairTest::disjoint();
  return PairTest::possible_from(t0_);
}

void AabbBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  out.push_back(Volume::box(boxes_[body], t0_, t0_));
}

}  // namespace ccd
