#pragma once
// `swept_aabb` (Knowledge::Exact): the box enclosing the body over the whole step
// [t0, t1], from the exact piecewise-quadratic trajectory (Trajectories::swept_bounds:
// piece end points and parabola vertices, wall reflections included), widened by the
// rounding slack. Test: box overlap. Conservative: the box contains the swept sphere.
// `earliest`: the box carries no timing, so it comes from speed bounds
// (bounds/speed_earliest.hpp: centre at the window's start, largest speed in the window).
// Static test: the box against the polygon by separating axes (ccd/queries/aabb_polygon.hpp),
// `earliest` from the speed bound and the centre's distance to the polygon at the window's start.
// Refresh: one body's box over its own window.
#include <bounds/bound.hpp>
#include <bounds/speed_earliest.hpp>

namespace ccd {

class SweptAabbBound final : public Bound {
 public:
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  PairTest test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                       const Aabb& polygon_box) const override;
  void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) override;
  Window window(std::uint32_t body) const override { return windows_[body]; }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;

 private:
  Aabb build(const StepContext& ctx, std::size_t i);
  std::vector<Aabb> boxes_;
  std::vector<Window> windows_;
  std::vector<SpeedBall> balls_;
};

}  // namespace ccd
