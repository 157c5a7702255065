#pragma once
// `horn_sat:M` (Knowledge::Bounded, default M = 4): the horn of `horn:M` (same sub-intervals,
// same half-widths r + A s^2 / 2 interpolated linearly) covered by cubes oriented along the
// body's velocity at t0: axes v/|v| and two perpendiculars (velocity_frame), centre p + v s.
// Each cube contains the horn's sphere whatever its orientation, so the cover is as valid as
// the axis-aligned one. Box: the world hull of the oriented trapezoids.
// Pair test: per sub-interval in time order, the 15-axis SAT sweep of
// bounds/oriented_trapezoid.hpp (projections linear in time; epsilon 1e-9 on |R_ij| for
// near-parallel edge-cross axes, conservative); `earliest` = the earliest possible contact.
// Zero (or < 1e-100) velocity: the axis-aligned frame.
// Walls: a body whose horn may pass a wall plane during the step uses the axis-aligned frame
// with the folded trapezoids of `horn:M` (conservative across reflections).
// Frames across steps: a body's velocity frame is kept from the step that built it while
// its velocity at t0 is the same, bit for bit (constant-velocity bodies between wall
// hits); any other velocity, or a folded step, rebuilds it, so every output is the one a
// fresh bound computes.
// Refresh: one body's trapezoids over its own window. Bodies over different windows are
// compared on the sub-intervals between the union of both bodies' breakpoints (each
// oriented trapezoid restricted by linear interpolation, half-widths widened by the
// interpolation's rounding error).
// Guarantee: conservative whenever |acceleration| <= A over the step.
#include <bounds/bound.hpp>
#include <bounds/oriented_trapezoid.hpp>

namespace ccd {

class HornSatBound final : public Bound {
 public:
  static constexpr int default_pieces = 4;
  explicit HornSatBound(int pieces = default_pieces);
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) override;
  Window window(std::uint32_t body) const override {
    const double* t = times_.data() + std::size_t{body} * (m_ + 1);
    return {t[0], t[m_]};
  }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;
  int pieces() const { return m_; }
  /// Oriented trapezoid j (0 <= j < M) of `body` from the last prepare.
  OrientedTrapezoid trapezoid(std::uint32_t body, int j) const;

 private:
  struct Ends {
    Vec3 c0, c1, h0, h1;
  };
  Aabb build(const StepContext& ctx, std::size_t i);
  void resize(std::size_t bodies);
  PairTest test_split(std::uint32_t a, std::uint32_t b) const;
  int m_;
  std::vector<Eigen::Matrix3d> frames_;
  std::vector<Vec3> framed_velocity_;  // the velocity frames_[i] was built from
  std::vector<unsigned char> framed_;  // 1: frames_[i] == velocity_frame(framed_velocity_[i])
  std::vector<Ends> ends_;
  std::vector<double> times_;         // per body, its M + 1 sub-interval ends
  std::vector<Trapezoid> scratch_;    // one body's axis-aligned trapezoids
};

}  // namespace ccd
