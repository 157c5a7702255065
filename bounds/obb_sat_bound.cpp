#include <bounds/obb_sat_bound.hpp>
#include <ccd/geometry/numeric_limits.hpp>
#include <bounds/rounding.hpp>
#include <bounds/shape_boxes.hpp>
#include <ccd/motion/piece_walk.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace ccd {
namespace {

/// Exact box of the centre's path of `body` over [u0, u1] (the pieces' tight boxes), given
/// k = Trajectories::piece_index(body, u0).
Aabb centre_path_box(const Trajectories& tr, std::size_t body, std::size_t k, double u0, double u1) {
  const auto ps = tr.pieces(body);
  // The piece before may end exactly at u0 (a break): include it, as swept_bounds does.
  if (k > 0 && ps[k - 1].t1 >= u0) --k;
  Aabb box = ps[k].centre_bounds(std::max(u0, ps[k].t0), std::min(u1, ps[k].t1));
  for (++k; k < ps.size() && ps[k].t0 <= u1; ++k)
    box.merge(ps[k].centre_bounds(std::max(u0, ps[k].t0), std::min(u1, ps[k].t1)));
  return box;
}

}  // namespace

ObbSatBound::ObbSatBound(int pieces) : m_(pieces) {
  if (pieces < 1) throw std::invalid_argument("obb_sat: pieces must be >= 1");
}

void ObbSatBound::resize(std::size_t n) {
  times_.resize(n * (m_ + 1));
  obbs_.resize(n * m_);
  hulls_.resize(n * m_);
  boxes_.resize(n);
}

Aabb ObbSatBound::build(const StepContext& ctx, std::size_t i) {
  const Trajectories& tr = *ctx.exact;
  const bool turns = ctx.motion->kind(i) != ShapeKind::Sphere;
  LocalBox local{Vec3::Zero(), Vec3::Constant(tr.radius(i))};
  if (turns) local = local_box(ctx.motion->proxy(i));
  const double R = tr.radius(i);  // the enclosing radius
  double* t = times_.data() + i * (m_ + 1);
  for (int j = 0; j <= m_; ++j) t[j] = j == m_ ? ctx.t1 : ctx.t0 + (ctx.t1 - ctx.t0) * j / m_;
  Aabb all;
  // The piece at each sub-interval's start, walked from the one at t0 (the state cursor's
  // when given): no search (ccd/motion/piece_walk.hpp).
  std::size_t k = ctx.piece_at_t0(i);
  for (int j = 0; j < m_; ++j) {
    const double s0 = t[j], s1 = t[j + 1];
    const double mid = 0.5 * (s0 + s1);
    k = piece_index_from(tr, i, k, s0);
    const Aabb path = centre_path_box(tr, i, k, s0, s1);
    const Vec3 dc = 0.5 * (path.lo + path.hi);
    const Vec3 dh = 0.5 * (path.hi - path.lo);
    OrientedBox& o = obbs_[i * m_ + j];
    double growth = 0.0;
    if (turns) {
      o.axes = body_rotation(*ctx.motion, i, mid);
      const double omega = ctx.motion->rotations().empty() ? 0.0 : ctx.motion->rotations().max_omega(i, s0, s1);
      const double theta = std::min(omega * std::max(mid - s0, s1 - mid), 2.0);
      // A free tumble's orientation at `mid` is evaluated within a stated error (0 for
      // constant spins): every point may be that much further out.
      growth = theta * R * (1.0 + 16.0 * kEps) + ctx.motion->pose_error(i, mid);
    } else {
      o.axes.setIdentity();
    }
    o.centre = dc + o.axes * local.centre;
    const double slack = rounding_slack(dc.cwiseAbs().maxCoeff() + dh.maxCoeff() + R + growth);
    o.half = local.half + o.axes.transpose().cwiseAbs() * dh;
    o.half.array() += growth + slack;
    // The enclosing ball's swept box holds the body too: keep it when it is smaller (fast
    // spin against the sub-interval, theta R near R).
    const Vec3 ball = dh.array() + (R + slack);
    if (turns && ball.prod() < o.half.prod()) {
      o.axes.setIdentity();
      o.centre = dc;
      o.half = ball;
    }
    Aabb& h = hulls_[i * m_ + j];
    h = o.hull();
    grow(h, slack);
    if (j == 0) all = h; else all.merge(h);
  }
  boxes_[i] = all;
  return all;
}

void ObbSatBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  if (!ctx.exact) throw std::invalid_argument("obb_sat needs the exact trajectories (StepContext::exact)");
  const std::size_t n = ctx.exact->size();
  resize(n);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = build(ctx, i);
}

void ObbSatBound::refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) {
  if (!ctx.exact) throw std::invalid_argument("obb_sat needs the exact trajectories (StepContext::exact)");
  if (boxes_.size() != ctx.exact->size()) resize(ctx.exact->size());  // no prepare before
  for (const std::uint32_t i : bodies) boxes[i] = build(ctx, i);
}

PairTest ObbSatBound::test(std::uint32_t a, std::uint32_t b) const {
  const Window w = common_window(window(a), window(b));
  if (w.t0 > w.t1 || !boxes_[a].overlaps(boxes_[b])) return PairTest::disjoint();
  const double* ta = times_.data() + std::size_t{a} * (m_ + 1);
  const double* tb = times_.data() + std::size_t{b} * (m_ + 1);
  const std::size_t oa = std::size_t{a} * m_, ob = std::size_t{b} * m_;
  // Sub-interval pairs in time order (a merge of the two partitions).
  int j = 0, k = 0;
  while (j < m_ && k < m_) {
    const double lo = std::max({ta[j], tb[k], w.t0});
    const double hi = std::min({ta[j + 1], tb[k + 1], w.t1});
    if (lo > w.t1) break;
    if (lo <= hi && hulls_[oa + j].overlaps(hulls_[ob + k]) && oriented_boxes_overlap(obbs_[oa + j], obbs_[ob + k]))
      return PairTest::possible_from(lo);
    if (ta[j + 1] < tb[k + 1]) {
      ++j;
    } else if (tb[k + 1] < ta[j + 1]) {
      ++k;
    } else {
      ++j;
      ++k;
    }
  }
  return PairTest::disjoint();
}

void ObbSatBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  const double* t = times_.data() + std::size_t{body} * (m_ + 1);
  for (int j = 0; j < m_; ++j) {
    const OrientedBox& o = box(body, j);
    out.push_back(Volume::oriented_box(o.centre, o.axes, o.half, t[j], t[j + 1]));
  }
}

}  // namespace ccd
