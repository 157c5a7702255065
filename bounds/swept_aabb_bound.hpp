#pragma once
// `swept_aabb` (Knowledge::Exact): the box enclosing the body over the whole step
// [t0, t1], from the exact piecewise-quadratic trajectory (Trajectories::swept_bounds:
// piece end points and parabola vertices, wall reflections included), widened by the
// rounding slack. Test: box overlap. Conservative: the box contains the swept sphere.
// `earliest` is t0 (a static box carries no timing).
#include <bounds/bound.hpp>

namespace ccd {

class SweptAabbBound final : public Bound {
 public:
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;

 private:
  std::vector<Aabb> boxes_;
  double t0_ = 0.0;
};

}  // namespace ccd
