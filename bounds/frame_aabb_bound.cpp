#include <bounds/frame_aabb_bound.hpp>
#include <bounds/rounding.hpp>
#include <bounds/shape_boxes.hpp>

namespace ccd {

void FrameAabbBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  t0_ = ctx.t0;
  const std::size_t n = ctx.start.size();
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState& s = ctx.start[i];
    const double slack = rounding_slack(s.position.cwiseAbs().maxCoeff() + s.radius);
    if (ctx.motion->kind(i) == ShapeKind::Sphere) {
      boxes[i] = Aabb::around(s.position, s.radius + slack);
    } else {
      boxes[i] = rotated_box(ctx.motion->proxy(i), body_rotation(*ctx.motion, i, ctx.t0), s.position);
      grow(boxes[i], slack);
    }
  }
  boxes_.assign(boxes.begin(), boxes.end());
}

PairTest FrameAabbBound::test(std::uint32_t a, std::uint32_t b) const {
  if (!boxes_[a].overlaps(boxes_[b])) return PairTest::disjoint();
  return PairTest::possible_from(t0_);
}

void FrameAabbBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  out.push_back(Volume::box(boxes_[body], t0_, t0_));
}

}  // namespace ccd
