#pragma once
// `sphere` (Knowledge::Instant): the body itself at the sample time t0 (= t1).
// Box: the sphere's AABB. Test: centre distance <= r1 + r2 (squared compare), i.e. the
// exact overlap test at the sample time. Conservative at the sample time only: a discrete
// method misses every contact that starts and ends between two samples.
// Static test: distance from the centre to the polygon <= r (point_polygon_closest).
// `earliest` is t0. Both sizes are widened by the rounding slack (rounding.hpp).
#include <bounds/bound.hpp>

namespace ccd {

class SphereBound final : public Bound {
 public:
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  PairTest test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                       const Aabb& polygon_box) const override;
  Window window(std::uint32_t) const override { return {t0_, t0_}; }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;

 private:
  struct Ball {
    Vec3 centre;
    double radius;
  };
  std::vector<Ball> balls_;
  double t0_ = 0.0;
};

}  // namespace ccd
