#include <bounds/horn_sat_bound.hpp>

#include <stdexcept>

namespace ccd {

HornSatBound::HornSatBound(int pieces) : m_(pieces) {
  if (pieces < 1) throw std::invalid_argument("horn_sat needs M >= 1 trapezoids");
}

void HornSatBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  const std::size_t n = ctx.start.size();
  frames_.resize(n);
  ends_.resize(n * m_);
  scratch_.resize(m_);
  times_.resize(m_ + 1);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState& s = ctx.start[i];
    const bool folded = horn_trapezoids(s, ctx.t0, ctx.t1, ctx.acceleration_bound, ctx.walls, m_, scratch_.data());
    if (i == 0) {
      for (int j = 0; j < m_; ++j) times_[j] = scratch_[j].t0;
      times_[m_] = scratch_[m_ - 1].t1;
    }
    const Eigen::Matrix3d frame = folded ? Eigen::Matrix3d::Identity() : velocity_frame(s.velocity);
    frames_[i] = frame;
    Ends* e = ends_.data() + i * m_;
    for (int j = 0; j < m_; ++j) {
      const Trapezoid& z = scratch_[j];
      e[j].c0 = 0.5 * (z.lo0 + z.hi0);
      e[j].c1 = 0.5 * (z.lo1 + z.hi1);
      // Half-widths; rounding of the midpoint is far below the faces' rounding slack.
      e[j].h0 = 0.5 * (z.hi0 - z.lo0);
      e[j].h1 = 0.5 * (z.hi1 - z.lo1);
      if (!folded) {  // a cube: any orientation contains the horn's sphere
        e[j].h0.setConstant(e[j].h0.maxCoeff());
        e[j].h1.setConstant(e[j].h1.maxCoeff());
      }
    }
    Aabb box = trapezoid(static_cast<std::uint32_t>(i), 0).hull();
    for (int j = 1; j < m_; ++j) box.merge(trapezoid(static_cast<std::uint32_t>(i), j).hull());
    boxes[i] = box;
  }
}

OrientedTrapezoid HornSatBound::trapezoid(std::uint32_t body, int j) const {
  const Ends& e = ends_[std::size_t{body} * m_ + j];
  return {times_[j], times_[j + 1], frames_[body], e.c0, e.c1, e.h0, e.h1};
}

PairTest HornSatBound::test(std::uint32_t a, std::uint32_t b) const {
  const SatFrames f(frames_[a], frames_[b]);
  const Ends* ea = ends_.data() + std::size_t{a} * m_;
  const Ends* eb = ends_.data() + std::size_t{b} * m_;
  for (int j = 0; j < m_; ++j) {
    const PairTest o = oriented_overlap(f, times_[j], times_[j + 1], ea[j].c0, ea[j].c1, ea[j].h0,
                                                ea[j].h1, eb[j].c0, eb[j].c1, eb[j].h0, eb[j].h1);
    if (o.possible()) return o;
  }
  return PairTest::disjoint();
}

}  // namespace ccd
