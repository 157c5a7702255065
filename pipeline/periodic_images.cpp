#include <pipeline/periodic_images.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {

ImageShift wrap_jump(const PeriodicBox& box, const Piece& prev, const Piece& next) {
  ImageShift s{0, 0, 0};
  const Vec3 end = prev.position(next.t0);
  for (std::size_t k = 0; k < 3; ++k) {
    const int i = static_cast<int>(k);
    if (box.wrap[k]) s[k] = static_cast<std::int32_t>(std::nearbyint((end[i] - next.p[i]) / box.period[i]));
  }
  return s;
}

const StepContext& PeriodicImages::begin(const StepContext& ctx) {
  source_ = ctx.motion;
  const Trajectories& motion = source_->centres();
  const PeriodicBox& box = *motion.periodic();
  const std::size_t n = motion.size();
  local_.reset(motion.horizon(), std::nullopt);
  owner_.clear();
  shift_.clear();
  states_.assign(ctx.start.begin(), ctx.start.end());
  std::vector<ImageShift> turns;
  for (std::size_t i = 0; i < n; ++i) {
    const auto ps = motion.pieces(i);
    const auto ls = motion.lows(i);
    // The pieces that overlap [t0, t1]: from the first ending at or after t0 to the one
    // containing t1; the piece containing t0 (the later one at a break, as the states
    // at t0 are taken) keeps its place, the others are unwrapped from it.
    auto first = std::lower_bound(ps.begin(), ps.end(), ctx.t0, [](const Piece& q, double x) { return q.t1 < x; });
    if (first == ps.end()) --first;
    const std::size_t i0 = static_cast<std::size_t>(first - ps.begin());
    const std::size_t ref = std::max(i0, motion.piece_index(i, ctx.t0));
    const std::size_t i1 = std::max(ref, motion.piece_index(i, ctx.t1));
    turns.assign(i1 - i0 + 1, ImageShift{0, 0, 0});
    for (std::size_t j = ref + 1; j <= i1; ++j)
      turns[j - i0] = shift_sum(turns[j - 1 - i0], wrap_jump(box, ps[j - 1], ps[j]));
    for (std::size_t j = ref; j-- > i0;)
      turns[j - i0] = shift_difference(turns[j + 1 - i0], wrap_jump(box, ps[j], ps[j + 1]));
    scratch_.resize(turns.size());
    for (std::size_t j = 0; j < turns.size(); ++j) scratch_[j] = image_offset(box, turns[j]);
    local_.append_body(motion.radius(i), ps.subspan(i0, i1 - i0 + 1), ls.subspan(i0, i1 - i0 + 1), scratch_);
    owner_.push_back(static_cast<std::uint32_t>(i));
    shift_.push_back(ImageShift{0, 0, 0});
  }
  ctx_ = ctx;
  ctx_.start = states_;
  ctx_.exact = ctx.exact ? &local_ : nullptr;
  ctx_.start_piece = {};  // the caller's piece indices are not the unwrapped paths'
  motion_.assign_images(*source_, local_, owner_, ctx.t0, ctx.t1);
  ctx_.motion = &motion_;
  if (ctx_.walls) {  // no walls on a wrapped axis: the unwrapped motion is free there
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      if (box.wrap[static_cast<std::size_t>(k)]) {
        ctx_.walls->min[k] = -kInf;
        ctx_.walls->max[k] = kInf;
        ctx_.walls->boundary[static_cast<std::size_t>(k)] = Boundary::Reflect;
      }
  }
  return ctx_;
}

bool PeriodicImages::add_images(const std::vector<Aabb>& boxes) {
  const Trajectories& source = source_->centres();
  const PeriodicBox& box = *source.periodic();
  const std::size_t n = source.size();
  std::vector<Piece> pieces;
  std::vector<PieceLow> lows;
  for (std::size_t i = 0; i < n; ++i) {
    box.for_each_image(boxes[i], [&](const ImageShift& s) {
      if (s == ImageShift{0, 0, 0}) return;
      const auto ps = local_.pieces(i);
      const auto ls = local_.lows(i);
      pieces.assign(ps.begin(), ps.end());  // copies: appending may move local_'s storage
      lows.assign(ls.begin(), ls.end());
      scratch_.assign(pieces.size(), image_offset(box, s));
      local_.append_body(source.radius(i), pieces, lows, scratch_);
      owner_.push_back(static_cast<std::uint32_t>(i));
      shift_.push_back(s);
      BodyState st = states_[i];  // evaluated as the states at t0 are: on the image's own piece
      const std::size_t j = local_.size() - 1;
      st.position = local_.position(j, ctx_.t0);
      st.velocity = local_.velocity(j, ctx_.t0);
      states_.push_back(st);
    });
  }
  ctx_.start = states_;
  if (states_.size() > n) motion_.assign_images(*source_, local_, owner_, ctx_.t0, ctx_.t1);
  return states_.size() > n;
}

}  // namespace ccd
