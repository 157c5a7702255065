#include <bounds/horn_bound.hpp>
#include <ccd/queries/aabb_polygon.hpp>

#include <stdexcept>

namespace ccd {

HornBound::HornBound(int pieces) : m_(pieces) {
  if (pieces < 1) throw std::invalid_argument("horn needs M >= 1 trapezoids");
}

Aabb HornBound::build(const StepContext& ctx, std::size_t i) {
  Trapezoid* z = traps_.data() + i * m_;
  horn_trapezoids(ctx.start[i], ctx.t0, ctx.t1, ctx.acceleration_bound, ctx.walls, m_, z);
  Aabb box = z[0].hull();
  for (int j = 1; j < m_; ++j) box.merge(z[j].hull());
  return box;
}

void HornBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  const std::size_t n = ctx.start.size();
  traps_.resize(n * m_);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = build(ctx, i);
}

void HornBound::refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) {
  if (traps_.size() != ctx.start.size() * m_) traps_.resize(ctx.start.size() * m_);  // no prepare before
  for (const std::uint32_t i : bodies) boxes[i] = build(ctx, i);
}

PairTest HornBound::test(std::uint32_t a, std::uint32_t b) const {
  const Trapezoid* za = traps_.data() + std::size_t{a} * m_;
  const Trapezoid* zb = traps_.data() + std::size_t{b} * m_;
  if (za[0].t0 != zb[0].t0 || za[m_ - 1].t1 != zb[m_ - 1].t1) return trapezoid_sequence_overlap(za, m_, zb, m_);
  for (int j = 0; j < m_; ++j) {
    const PairTest o = trapezoid_overlap(za[j], zb[j]);
    if (o.possible()) return o;
  }
  return PairTest::disjoint();
}

PairTest HornBound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                                const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  const Trapezoid* z = traps_.data() + std::size_t{body} * m_;
  for (int j = 0; j < m_; ++j) {
    const Aabb hull = z[j].hull();
    if (hull.overlaps(polygon_box) && aabb_polygon_overlap(hull, polygon, aabb_polygon_rounding(hull, polygon)))
      return PairTest::possible_from(z[j].t0);
  }
  return PairTest::disjoint();
}

void HornBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  // Each moving trapezoid as the box it sweeps over its sub-interval (its hull).
  const Trapezoid* z = traps_.data() + std::size_t{body} * m_;
  for (int j = 0; j < m_; ++j) out.push_back(Volume::box(z[j].hull(), z[j].t0, z[j].t1));
}

}  // namespace ccd
