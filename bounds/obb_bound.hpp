#pragma once
// `obb` (Knowledge::Instant): the body's oriented bounding box at the sample time t0
// (= t1): the tightest box of the shape on the body's own axes (bounding the body-frame
// points grown by the radius; bounds/shape_boxes.hpp), turned and placed by the body's
// pose. Box: the OBB's world AABB. Test: the 15-axis separating-axis test of the two
// oriented boxes (bounds/oriented_box.hpp; robust to parallel edges). A sphere, and every
// body of a sphere scene, is the axis-aligned cube of its ball. Conservative at the sample
// time only, like every discrete bound. Sizes are widened by the rounding slack.
#include <bounds/bound.hpp>
#include <bounds/oriented_box.hpp>

namespace ccd {

class ObbBound final : public Bound {
 public:
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  Window window(std::uint32_t) const override { return {t0_, t0_}; }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;
  /// The oriented box of `body` from the last prepare.
  const OrientedBox& box(std::uint32_t body) const { return obbs_[body]; }

 private:
  std::vector<OrientedBox> obbs_;
  std::vector<Aabb> boxes_;
  double t0_ = 0.0;
};

}  // namespace ccd
