#include <bounds/horn_sat_bound.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace ccd {
namespace {

// The part of oriented trapezoid `z` over [u0, u1] inside [z.t0, z.t1]: centre and
// half-widths interpolated linearly; the half-widths grow by the interpolation's rounding
// error (the time fraction's error times the change of centre and half-widths, plus 4 ulps
// of their magnitude; a centre error is a world vector, so its 1-norm covers any axis).
OrientedTrapezoid restrict_oriented(const OrientedTrapezoid& z, double u0, double u1) {
  if (u0 == z.t0 && u1 == z.t1) return z;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  OrientedTrapezoid r = z;
  r.t0 = u0;
  r.t1 = u1;
  const double h = z.t1 - z.t0;
  if (!(h > 0.0)) {
    r.h0 = r.h1 = z.h0.cwiseMax(z.h1);
    return r;
  }
  const double du = 4.0 * eps * (std::abs(z.t0) + std::abs(z.t1) + std::abs(u0) + std::abs(u1)) / h + 4.0 * eps;
  const double f0 = std::clamp((u0 - z.t0) / h, 0.0, 1.0);
  const double f1 = std::clamp((u1 - z.t0) / h, 0.0, 1.0);
  const Vec3 dc = z.c1 - z.c0;
  const Vec3 dh = z.h1 - z.h0;
  const double centre_error =
      du * dc.cwiseAbs().sum() + 4.0 * eps * (z.c0.cwiseAbs().sum() + z.c1.cwiseAbs().sum());
  const Vec3 widen = (du * dh.cwiseAbs()).array() + 4.0 * eps * z.h0.cwiseMax(z.h1).maxCoeff() + centre_error;
  r.c0 = z.c0 + dc * f0;
  r.c1 = z.c0 + dc * f1;
  r.h0 = z.h0 + dh * f0 + widen;
  r.h1 = z.h0 + dh * f1 + widen;
  return r;
}

}  // namespace

HornSatBound::HornSatBound(int pieces) : m_(pieces) {
  if (pieces < 1) throw std::invalid_argument("horn_sat needs M >= 1 trapezoids");
}

Aabb HornSatBound::build(const StepContext& ctx, std::size_t i) {
  const BodyState& s = ctx.start[i];
  const bool folded = horn_trapezoids(s, ctx.t0, ctx.t1, ctx.acceleration_bound, ctx.walls, m_, scratch_.data());
  double* t = times_.data() + i * (m_ + 1);
  for (int j = 0; j < m_; ++j) t[j] = scratch_[j].t0;
  t[m_] = scratch_[m_ - 1].t1;
  if (folded) {
    frames_[i].setIdentity();
    framed_[i] = 0;
  } else if (!framed_[i] || std::memcmp(framed_velocity_[i].data(), s.velocity.data(), sizeof(Vec3)) != 0) {
    // The frame is a function of the velocity's bits: kept while they are unchanged.
    frames_[i] = velocity_frame(s.velocity);
    framed_velocity_[i] = s.velocity;
    framed_[i] = 1;
  }
  Ends* e = ends_.data() + i * m_;
  const Eigen::Matrix3d abs_axes = frames_[i].cwiseAbs();
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo = Vec3::Constant(inf), hi = Vec3::Constant(-inf);  // the hull of trapezoid(i, j).hull()
  for (int j = 0; j < m_; ++j) {
    const Trapezoid& z = scratch_[j];
    Ends& ej = e[j];
    ej.c0 = 0.5 * (z.lo0 + z.hi0);
    ej.c1 = 0.5 * (z.lo1 + z.hi1);
    // Half-widths; rounding of the midpoint is far below the faces' rounding slack.
    ej.h0 = 0.5 * (z.hi0 - z.lo0);
    ej.h1 = 0.5 * (z.hi1 - z.lo1);
    if (!folded) {  // a cube: any orientation contains the horn's sphere
      ej.h0.setConstant(ej.h0.maxCoeff());
      ej.h1.setConstant(ej.h1.maxCoeff());
    }
    merge_oriented_hull(abs_axes, ej.c0, ej.c1, ej.h0, ej.h1, lo, hi);
  }
  return {lo, hi};
}

void HornSatBound::resize(std::size_t n) {
  frames_.resize(n);
  framed_velocity_.resize(n);
  framed_.resize(n, 0);
  ends_.resize(n * m_);
  scratch_.resize(m_);
  times_.resize(n * (m_ + 1));
}

void HornSatBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  const std::size_t n = ctx.start.size();
  resize(n);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = build(ctx, i);
}

void HornSatBound::refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) {
  const std::size_t n = ctx.start.size();
  if (frames_.size() != n) resize(n);  // no prepare before: room for every body
  for (const std::uint32_t i : bodies) boxes[i] = build(ctx, i);
}

OrientedTrapezoid HornSatBound::trapezoid(std::uint32_t body, int j) const {
  const Ends& e = ends_[std::size_t{body} * m_ + j];
  const double* t = times_.data() + std::size_t{body} * (m_ + 1);
  return {t[j], t[j + 1], frames_[body], e.c0, e.c1, e.h0, e.h1};
}

PairTest HornSatBound::test(std::uint32_t a, std::uint32_t b) const {
  const double* times = times_.data() + std::size_t{a} * (m_ + 1);
  const double* tb = times_.data() + std::size_t{b} * (m_ + 1);
  if (times[0] != tb[0] || times[m_] != tb[m_]) return test_split(a, b);
  const SatFrames f(frames_[a], frames_[b]);
  const Ends* ea = ends_.data() + std::size_t{a} * m_;
  const Ends* eb = ends_.data() + std::size_t{b} * m_;
  for (int j = 0; j < m_; ++j) {
    const PairTest o = oriented_overlap(f, times[j], times[j + 1], ea[j].c0, ea[j].c1, ea[j].h0,
                                                ea[j].h1, eb[j].c0, eb[j].c1, eb[j].h0, eb[j].h1);
    if (o.possible()) return o;
  }
  return PairTest::disjoint();
}

PairTest HornSatBound::test_split(std::uint32_t a, std::uint32_t b) const {
  const double* ta = times_.data() + std::size_t{a} * (m_ + 1);
  const double* tb = times_.data() + std::size_t{b} * (m_ + 1);
  const double lo = std::max(ta[0], tb[0]);
  const double hi = std::min(ta[m_], tb[m_]);
  if (lo > hi) return PairTest::disjoint();
  const SatFrames f(frames_[a], frames_[b]);
  int i = 0, j = 0;
  while (i < m_ && ta[i + 1] < lo) ++i;
  while (j < m_ && tb[j + 1] < lo) ++j;
  while (i < m_ && j < m_) {
    const double u0 = std::max({ta[i], tb[j], lo});
    const double u1 = std::min({ta[i + 1], tb[j + 1], hi});
    if (u0 <= u1) {
      const OrientedTrapezoid x = restrict_oriented(trapezoid(a, i), u0, u1);
      const OrientedTrapezoid y = restrict_oriented(trapezoid(b, j), u0, u1);
      const PairTest o = oriented_overlap(f, u0, u1, x.c0, x.c1, x.h0, x.h1, y.c0, y.c1, y.h0, y.h1);
      if (o.possible()) return o;
    }
    if (u1 >= hi) break;
    if (ta[i + 1] < tb[j + 1]) {
      ++i;
    } else if (tb[j + 1] < ta[i + 1]) {
      ++j;
    } else {
      ++i;
      ++j;
    }
  }
  return PairTest::disjoint();
}

void HornSatBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  // Each moving oriented trapezoid as the box on its own axes that holds both its ends
  // (the box at every time in between is their interpolation, so it lies in there too).
  for (int j = 0; j < m_; ++j) {
    const OrientedTrapezoid z = trapezoid(body, j);
    const Vec3 l0 = z.axes.transpose() * z.c0, l1 = z.axes.transpose() * z.c1;
    const Vec3 lo = (l0 - z.h0).cwiseMin(l1 - z.h1), hi = (l0 + z.h0).cwiseMax(l1 + z.h1);
    out.push_back(Volume::oriented_box(z.axes * (0.5 * (lo + hi)), z.axes, 0.5 * (hi - lo), z.t0, z.t1));
  }
}

}  // namespace ccd
