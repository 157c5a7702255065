#pragma once
// `aabb` (Knowledge::Instant): the box around the body at the sample time t0 (= t1).
// Test: always true for a pair the broad phase reported (their boxes overlap, and that is
// the whole test); called on any pair it checks the box overlap. Conservative at the
// sample time only (like `sphere`), looser: boxes overlap for spheres up to sqrt(3) (r1 +
// r2) apart. `earliest` is t0. Boxes are widened by the rounding slack.
#include <bounds/bound.hpp>

namespace ccd {

class AabbBound final : public Bound {
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
