#include <pipeline/periodic_images.hpp>
#include <pipeline/scheduler_images.hpp>

#include <algorithm>

namespace ccd {
namespace {

ImageShift plus(const ImageShift& x, const ImageShift& y) { return {x[0] + y[0], x[1] + y[1], x[2] + y[2]}; }
ImageShift minus(const ImageShift& x, const ImageShift& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }
constexpr ImageShift kZero{0, 0, 0};

}  // namespace

void SchedulerImages::begin(const Trajectories& motion) {
  motion_ = &motion;
  box_ = *motion.periodic();
  const std::size_t n = motion.size();
  first_turn_.assign(1, 0);
  turns_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const auto ps = motion.pieces(i);
    for (std::size_t j = 0; j < ps.size(); ++j)
      turns_.push_back(j == 0 ? kZero : plus(turns_.back(), wrap_jump(box_, ps[j - 1], ps[j])));
    first_turn_.push_back(static_cast<std::uint32_t>(turns_.size()));
  }
  owner_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) owner_[i] = i;
  shift_.assign(n, kZero);
  images_.assign(n, {});
  pool_.clear();
  // The parking area lies below the box by twice its largest extent (moved further out by
  // keep_clear when a box reaches it); pooled points are 2^-12 extents apart.
  const double extent = (box_.max - box_.min).maxCoeff();
  park_ = box_.min - Vec3::Constant(2.0 * extent);
  step_ = 0x1p-12 * extent;
}

ImageShift SchedulerImages::relative(std::uint32_t x, std::uint32_t y) const {
  return minus(shift_[y], shift_[x]);
}

void SchedulerImages::set_home(std::uint32_t body, double t) {
  const std::size_t j = motion_->piece_index(body, t);
  shift_[body] = minus(kZero, turns_[first_turn_[body] + j]);
}

BodyState SchedulerImages::state(std::uint32_t slot, double t) const {
  const std::uint32_t o = owner_[slot];
  const std::size_t j = motion_->piece_index(o, t);
  Piece q = motion_->pieces(o)[j];
  PieceLow low = motion_->lows(o)[j];
  const ImageShift s = plus(turns_[first_turn_[o] + j], shift_[slot]);
  if (s != kZero) shift_piece(q, low, image_offset(box_, s));
  return {q.position(t), q.velocity(t), motion_->radius(o)};
}

Aabb SchedulerImages::parked(std::uint32_t slot) const {
  const Vec3 p = park_ - Vec3::Constant(static_cast<double>(slot) * step_);
  return {p, p};
}

std::uint32_t SchedulerImages::take_slot(std::vector<Aabb>& boxes) {
  if (pool_.empty()) {  // grow by an eighth (at least 16): few changes of the slot count
    const std::size_t old = owner_.size();
    const std::size_t add = std::max<std::size_t>(16, old / 8);
    for (std::size_t k = 0; k < add; ++k) {
      const auto s = static_cast<std::uint32_t>(old + k);
      owner_.push_back(kFree);
      shift_.push_back(kZero);
      boxes.push_back(parked(s));
    }
    for (std::size_t k = add; k-- > 0;) pool_.push_back(static_cast<std::uint32_t>(old + k));
  }
  const std::uint32_t s = pool_.back();
  pool_.pop_back();
  return s;
}

void SchedulerImages::set_images(std::uint32_t body, const Aabb& home_box, std::vector<Aabb>& boxes,
                                 std::vector<std::uint32_t>& images, std::vector<std::uint32_t>& freed) {
  std::vector<std::uint32_t>& mine = images_[body];
  std::size_t used = 0;
  const ImageShift home = shift_[body];
  box_.for_each_image(home_box, [&](const ImageShift& s) {
    if (s == kZero) return;
    std::uint32_t slot;
    if (used < mine.size()) {
      slot = mine[used];
    } else {
      slot = take_slot(boxes);
      mine.push_back(slot);
    }
    ++used;
    owner_[slot] = body;
    shift_[slot] = plus(home, s);
    images.push_back(slot);
  });
  for (std::size_t k = used; k < mine.size(); ++k) {
    const std::uint32_t s = mine[k];
    owner_[s] = kFree;
    boxes[s] = parked(s);
    pool_.push_back(s);
    freed.push_back(s);
  }
  mine.resize(used);
}

void SchedulerImages::keep_clear(const Aabb& active, std::vector<Aabb>& boxes,
                                 std::vector<std::uint32_t>& moved) {
  // Pooled points lie at x <= park_.x: a box starting above it on x meets none of them.
  if (active.lo.x() > park_.x()) return;
  const double margin = 2.0 * ((active.hi - active.lo).maxCoeff() + (box_.max - box_.min).maxCoeff());
  park_ = active.lo - Vec3::Constant(margin);
  for (const std::uint32_t s : pool_) {
    boxes[s] = parked(s);
    moved.push_back(s);
  }
}

void SchedulerImages::append_path(Trajectories& out, std::uint32_t slot, double u0, double u1) {
  const std::uint32_t o = owner_[slot];
  const auto ps = motion_->pieces(o);
  const auto ls = motion_->lows(o);
  // From the first piece ending at or after u0 to the one containing u1.
  auto first = std::lower_bound(ps.begin(), ps.end(), u0, [](const Piece& q, double x) { return q.t1 < x; });
  if (first == ps.end()) --first;
  const auto j0 = static_cast<std::size_t>(first - ps.begin());
  const std::size_t j1 = std::max(j0, motion_->piece_index(o, u1));
  offsets_.resize(j1 - j0 + 1);
  for (std::size_t j = j0; j <= j1; ++j)
    offsets_[j - j0] = image_offset(box_, plus(turns_[first_turn_[o] + j], shift_[slot]));
  out.append_body(motion_->radius(o), ps.subspan(j0, j1 - j0 + 1), ls.subspan(j0, j1 - j0 + 1), offsets_);
}

const Trajectories& SchedulerImages::view(std::span<const std::uint32_t> slots, double u0, double u1) {
  listed_.assign(owner_.size(), 0);
  for (const std::uint32_t s : slots) listed_[s] = 1;
  view_.reset(motion_->horizon(), std::nullopt);
  for (std::uint32_t s = 0; s < owner_.size(); ++s) {
    if (listed_[s])
      append_path(view_, s, u0, u1);
    else
      view_.append_body(0.0, {}, {}, {});
  }
  return view_;
}

const Trajectories& SchedulerImages::pair_view(std::uint32_t x, std::uint32_t y, double u0, double u1) {
  pair_view_.reset(motion_->horizon(), std::nullopt);
  append_path(pair_view_, x, u0, u1);
  append_path(pair_view_, y, u0, u1);
  return pair_view_;
}

}  // namespace ccd
