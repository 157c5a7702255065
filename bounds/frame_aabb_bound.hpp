#pragma once
// `frame_aabb` (Knowledge::Instant): the tightest AABB of the body as it is turned at the
// sample time t0 (= t1), recomputed at every sample: on each world axis the extremes of
// the rotated shape (closed form from the orientation: a box's corners, a capsule's two
// ends grown by its radius, a hull's points; bounds/shape_boxes.hpp). A sphere, and every body of
// a sphere scene, is the box of its ball, as for `aabb`. Test: box overlap. Conservative at
// the sample time only, like every discrete bound: it contains the shape, so a pair that
// touches at the sample is always reported. Boxes are widened by the rounding slack.
#include <bounds/bound.hpp>

namespace ccd {

class FrameAabbBound final : public Bound {
 public:
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  Window window(std::uint32_t) const override { return {t0_, t0_}; }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;

 private:
  std::vector<Aabb> boxes_;
  double t0_ = 0.0;
};

}  // namespace ccd
