#include <bounds/obb_bound.hpp>
#include <bounds/rounding.hpp>
#include <bounds/shape_boxes.hpp>

namespace ccd {

void ObbBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  t0_ = ctx.t0;
  const std::size_t n = ctx.start.size();
  boxes.resize(n);
  obbs_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState& s = ctx.start[i];
    const double slack = rounding_slack(s.position.cwiseAbs().maxCoeff() + s.radius);
    OrientedBox& o = obbs_[i];
    if (ctx.motion->kind(i) == ShapeKind::Sphere) {
      o.centre = s.position;
      o.axes.setIdentity();
      o.half = Vec3::Constant(s.radius + slack);
    } else {
      const LocalBox local = local_box(ctx.motion->proxy(i));
      o.axes = body_rotation(*ctx.motion, i, ctx.t0);
      o.centre = s.position + o.axes * local.centre;
      o.half = local.half.array() + slack;
    }
    boxes[i] = o.hull();
    grow(boxes[i], slack);
  }
  boxes_.assign(boxes.begin(), boxes.end());
}

PairTest ObbBound::test(std::uint32_t a, std::uint32_t b) const {
  if (!boxes_[a].overlaps(boxes_[b]) || !oriented_boxes_overlap(obbs_[a], obbs_[b])) return PairTest::disjoint();
  return PairTest::possible_from(t0_);
}

void ObbBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  const OrientedBox& o = obbs_[body];
  out.push_back(Volume::oriented_box(o.centre, o.axes, o.half, t0_, t0_));
}

}  // namespace ccd
