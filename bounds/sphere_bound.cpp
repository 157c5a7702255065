#include <bounds/rounding.hpp>
#include <bounds/sphere_bound.hpp>

namespace ccd {

void SphereBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  t0_ = ctx.t0;
  const std::size_t n = ctx.start.size();
  balls_.resize(n);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState& s = ctx.start[i];
    const double r = s.radius + rounding_slack(s.position.cwiseAbs().maxCoeff() + s.radius);
    balls_[i] = {s.position, r};
    boxes[i] = Aabb::around(s.position, r);
  }
}

PairTest SphereBound::test(std::uint32_t a, std::uint32_t b) const {
  const Ball& x = balls_[a];
  const Ball& y = balls_[b];
  const double R = x.radius + y.radius;
  if ((x.centre - y.centre).squaredNorm() > R * R) return PairTest::disjoint();
  return PairTest::possible_from(t0_);
}

}  // namespace ccd
