#include <bounds/capsule_bound.hpp>
#include <bounds/rounding.hpp>
#include <ccd/motion/piece_walk.hpp>
#include <ccd/queries/point_polygon.hpp>
#include <ccd/queries/point_segment.hpp>
#include <ccd/queries/segment_polygon.hpp>
#include <ccd/queries/segment_segment.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ccd {
Aabb CapsuleBound::build(const StepContext& ctx, std::size_t i) {
  const Trajectories& tr = *ctx.exact;
  // Every piece is found from the one at t0 (the state cursor's when the pipeline has it):
  // no search (ccd/motion/piece_walk.hpp).
  const std::size_t k = ctx.piece_at_t0(i);
  const auto pieces = tr.pieces(i);
  const Vec3 p0 = pieces[k].position(ctx.t0);
  const Vec3 p1 = pieces[piece_index_from(tr, i, k, ctx.t1)].position(ctx.t1);
  double e = 0.0;
  const Piece* q = pieces.data() + k;
  for (; q != pieces.data() + pieces.size() && q->t0 <= ctx.t1; ++q) {
    const double u0 = std::max(ctx.t0, q->t0);
    const double u1 = std::min(ctx.t1, q->t1);
    if (u1 < u0) continue;
    const double hk = u1 - u0;
    const double dev = q->a.norm() * hk * hk / 8.0;
    const double ends = q->t0 <= ctx.t0 && q->t1 >= ctx.t1
                            ? 0.0  // the single piece's chord is S itself
                            : std::max(point_segment_distance(q->position(u0), p0, p1),
                                       point_segment_distance(q->position(u1), p0, p1));
    e = std::max(e, ends + dev);
  }
  Aabb swept = swept_bounds_from(tr, i, k, ctx.t0, ctx.t1);
  const double magnitude = swept.lo.cwiseAbs().cwiseMax(swept.hi.cwiseAbs()).maxCoeff() + e;
  const double slack = rounding_slack(magnitude);
  const double radius = tr.radius(i) + e + slack;
  capsules_[i] = {p0, p1, radius, max_speed_from(tr, i, k, ctx.t0, ctx.t1), tr.radius(i)};
  swept.lo.array() -= slack;
  swept.hi.array() += slack;
  const Aabb cap{p0.cwiseMin(p1).array() - radius, p0.cwiseMax(p1).array() + radius};
  return {swept.lo.cwiseMax(cap.lo), swept.hi.cwiseMin(cap.hi)};
}

void CapsuleBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  if (!ctx.exact) throw std::invalid_argument("capsule needs the exact trajectories (StepContext::exact)");
  const std::size_t n = ctx.exact->size();
  capsules_.resize(n);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = build(ctx, i);
  windows_.assign(n, Window{ctx.t0, ctx.t1});
}

void CapsuleBound::refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) {
  if (!ctx.exact) throw std::invalid_argument("capsule needs the exact trajectories (StepContext::exact)");
  if (capsules_.size() != ctx.exact->size()) {  // no prepare before: room for every body
    capsules_.resize(ctx.exact->size());
    windows_.resize(ctx.exact->size());
  }
  for (const std::uint32_t i : bodies) {
    boxes[i] = build(ctx, i);
    windows_[i] = {ctx.t0, ctx.t1};
  }
}

PairTest CapsuleBound::test(std::uint32_t a, std::uint32_t b) const {
  const Window w = common_window(windows_[a], windows_[b]);
  if (w.t0 > w.t1) return PairTest::disjoint();
  const Capsule& x = capsules_[a];
  const Capsule& y = capsules_[b];
  const SegmentSegmentResult c = segment_segment_closest(x.p0, x.p1, y.p0, y.p1);
  const double R = x.radius + y.radius;
  const double closest_error = 16.0 * std::numeric_limits<double>::epsilon() *
                               ((x.p1 - x.p0).squaredNorm() + (y.p1 - y.p0).squaredNorm() +
                                (x.p0 - y.p0).squaredNorm());
  if (c.distance_squared > R * R + closest_error) return PairTest::disjoint();
  const double t = speed_earliest({x.p0, windows_[a].t0, x.speed, x.body_radius},
                                  {y.p0, windows_[b].t0, y.speed, y.body_radius});
  return PairTest::possible_from(std::min(t, w.t1));
}

void CapsuleBound::test_pairs(std::span<const BodyPair> pairs, std::vector<BodyPair>& passed,
                              std::vector<double>& earliest) const {
  // A broad phase's pairs name scattered bodies, so each test would wait for two capsules
  // and two windows from memory; asking for those of the pair kAhead places on while this
  // one is tested overlaps the waits (kernels_bench, pipeline/continuous/capsule).
  constexpr std::size_t kAhead = 8;
  const auto fetch = [this](std::uint32_t body) {
    const char* c = reinterpret_cast<const char*>(capsules_.data() + body);
    __builtin_prefetch(c);
    __builtin_prefetch(c + sizeof(Capsule) - 1);
    __builtin_prefetch(windows_.data() + body);
  };
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (i + kAhead < pairs.size()) {
      fetch(pairs[i + kAhead].a);
      fetch(pairs[i + kAhead].b);
    }
    const PairTest t = test(pairs[i].a, pairs[i].b);
    if (t.possible()) {
      passed.push_back(pairs[i]);
      earliest.push_back(t.earliest);
    }
  }
}

PairTest CapsuleBound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                                   const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  const Capsule& c = capsules_[body];
  const double slack = std::max(static_rounding_slack(c.p0, polygon), static_rounding_slack(c.p1, polygon));
  const double R = c.radius + slack;
  if (segment_polygon_closest(c.p0, c.p1, polygon).distance_squared > R * R) return PairTest::disjoint();
  const Window w = windows_[body];
  const double d = std::sqrt(point_polygon_closest(c.p0, polygon).distance_squared);
  return PairTest::possible_from(std::min(speed_earliest_static({c.p0, w.t0, c.speed, c.body_radius}, d, slack), w.t1));
}

void CapsuleBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  const Capsule& c = capsules_[body];
  out.push_back(Volume::capsule(c.p0, c.p1, c.radius, windows_[body].t0, windows_[body].t1));
}

}  // namespace ccd
