#include <bounds/rounding.hpp>
#include <bounds/sphere_bound.hpp>
#include <ccd/queries/point_polygon.hpp>

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

PairTest SphereBound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                                  const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  const Ball& x = balls_[body];
  const double r = x.radius + static_rounding_slack(x.centre, polygon);
  if (point_polygon_closest(x.centre, polygon).distance_squared > r * r) return PairTest::disjoint();
  return PairTest::possible_from(t0_);
}

void SphereBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  out.push_back(Volume::sphere(balls_[body].centre, balls_[body].radius, t0_, t0_));
}

}  // namespace ccd
