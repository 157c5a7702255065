#pragma once
// `obb_sat:M` (Knowledge::Exact, default M = 4): the step (a body's window) split into M
// equal sub-intervals; on each, one oriented box that holds the body over the whole
// sub-interval [s0, s1], with m its midpoint:
//  - axes: the body's orientation at m; the shape's body-frame box (bounds/shape_boxes.hpp)
//    turned by it;
//  - grown on every axis by theta R: theta = max |omega| over the sub-interval x
//    max(m - s0, s1 - m) bounds the angle between the orientation at any t in it and at m
//    (at most 2), and a rotation by theta moves a point at distance <= R (the enclosing
//    radius) from the centre of rotation by at most theta R;
//  - grown by the sweep of the centre: the exact box D of the centre's path over the
//    sub-interval (reflections included), centred on D's centre and widened by |axes^T| of
//    D's half-widths.
// When the swept box of the enclosing ball (world axes, half-widths R + D's) has the smaller
// volume (fast spin: theta R near R), that box is used instead: it holds the body too.
// A sphere, and every body of a sphere scene, uses the world axes and no rotation growth:
// its box is the swept sphere's box on the sub-interval. Box: the union of the M boxes'
// world hulls. Pair test: in time order, every pair of sub-intervals of a and b that
// overlap inside the common window, the 15-axis SAT of their boxes
// (bounds/oriented_box.hpp); `earliest` = the start of the first overlapping pair (clamped
// to the common window). Sizes are widened by the rounding slack.
// Guarantee: conservative for the exact motion and the prescribed spin (it contains the
// body at every instant of the step); tighter than the enclosing sphere's bounds for long
// and flat bodies that turn little per sub-interval.
#include <bounds/bound.hpp>
#include <bounds/oriented_box.hpp>

namespace ccd {

class ObbSatBound final : public Bound {
 public:
  static constexpr int default_pieces = 4;
  explicit ObbSatBound(int pieces = default_pieces);
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) override;
  Window window(std::uint32_t body) const override {
    const double* t = times_.data() + std::size_t{body} * (m_ + 1);
    return {t[0], t[m_]};
  }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;
  int pieces() const { return m_; }
  /// Oriented box j (0 <= j < M) of `body` from the last prepare or refresh.
  const OrientedBox& box(std::uint32_t body, int j) const { return obbs_[std::size_t{body} * m_ + j]; }

 private:
  Aabb build(const StepContext& ctx, std::size_t i);
  void resize(std::size_t n);
  int m_;
  std::vector<double> times_;     // per body, its M + 1 sub-interval ends
  std::vector<OrientedBox> obbs_; // per body, M boxes
  std::vector<Aabb> hulls_;       // per body, the M boxes' world hulls
  std::vector<Aabb> boxes_;       // per body, the union of its hulls
};

}  // namespace ccd
