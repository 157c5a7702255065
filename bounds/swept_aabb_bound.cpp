#include <bounds/rounding.hpp>
#include <bounds/swept_aabb_bound.hpp>
#include <ccd/motion/piece_walk.hpp>
#include <ccd/queries/aabb_polygon.hpp>
#include <ccd/queries/point_polygon.hpp>

#include <cmath>

#include <algorithm>
#include <stdexcept>

namespace ccd {

Aabb SweptAabbBound::build(const StepContext& ctx, std::size_t i) {
  const Trajectories& tr = *ctx.exact;
  const std::size_t k = ctx.piece_at_t0(i);  // the state cursor's when given: no search
  balls_[i] = {tr.pieces(i)[k].position(ctx.t0), ctx.t0, max_speed_from(tr, i, k, ctx.t0, ctx.t1), tr.radius(i)};
  Aabb box = swept_bounds_from(tr, i, k, ctx.t0, ctx.t1);
  const double slack = rounding_slack(box.lo.cwiseAbs().cwiseMax(box.hi.cwiseAbs()).maxCoeff());
  box.lo.array() -= slack;
  box.hi.array() += slack;
  return box;
}

void SweptAabbBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  if (!ctx.exact) throw std::invalid_argument("swept_aabb needs the exact trajectories (StepContext::exact)");
  const std::size_t n = ctx.exact->size();
  boxes.resize(n);
  balls_.resize(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = build(ctx, i);
  boxes_.assign(boxes.begin(), boxes.end());
  windows_.assign(n, Window{ctx.t0, ctx.t1});
}

void SweptAabbBound::refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) {
  if (!ctx.exact) throw std::invalid_argument("swept_aabb needs the exact trajectories (StepContext::exact)");
  if (boxes_.size() != ctx.exact->size()) {  // no prepare before: room for every body
    boxes_.resize(ctx.exact->size());
    windows_.resize(ctx.exact->size());
    balls_.resize(ctx.exact->size());
  }
  for (const std::uint32_t i : bodies) {
    boxes_[i] = boxes[i] = build(ctx, i);
    windows_[i] = {ctx.t0, ctx.t1};
  }
}

PairTest SweptAabbBound::test(std::uint32_t a, std::uint32_t b) const {
  const Window w = common_window(windows_[a], windows_[b]);
  if (w.t0 > w.t1 || !boxes_[a].overlaps(boxes_[b])) return PairTest::disjoint();
  return PairTest::possible_from(std::min(speed_earliest(balls_[a], balls_[b]), w.t1));
}

PairTest SweptAabbBound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                                     const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  if (!aabb_polygon_overlap(body_box, polygon, aabb_polygon_rounding(body_box, polygon))) return PairTest::disjoint();
  const SpeedBall& b = balls_[body];
  const double d = std::sqrt(point_polygon_closest(b.centre, polygon).distance_squared);
  return PairTest::possible_from(
      std::min(speed_earliest_static(b, d, static_rounding_slack(b.centre, polygon)), windows_[body].t1));
}

void SweptAabbBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  out.push_back(Volume::box(boxes_[body], windows_[body].t0, windows_[body].t1));
}

}  // namespace ccd
