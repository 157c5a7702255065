#include <ccd/broad_phase/verlet_list.hpp>

#include <algorithm>
#include <cmath>

namespace ccd::detail {
namespace {

constexpr std::uint32_t kMaxBackoff = 64;

bool inside(const Aabb& box, const Aabb& fat) {
  return box.lo.x() >= fat.lo.x() && box.lo.y() >= fat.lo.y() && box.lo.z() >= fat.lo.z() &&
         box.hi.x() <= fat.hi.x() && box.hi.y() <= fat.hi.y() && box.hi.z() <= fat.hi.z();
}

double largest_extent(const Aabb& b) { return (b.hi - b.lo).maxCoeff(); }

// The largest change of any face between two boxes.
double face_motion(const Aabb& now, const Aabb& then) {
  return std::max((now.lo - then.lo).cwiseAbs().maxCoeff(), (now.hi - then.hi).cwiseAbs().maxCoeff());
}

}  // namespace

bool VerletList::serve(std::span<const Aabb> boxes, std::vector<BodyPair>& out, std::uint64_t& box_tests) {
  const std::size_t n = boxes.size();
  if (anchor_.size() == n && anchor_frames_ < UINT32_MAX) ++anchor_frames_;
  if (!listed_) return false;
  bool all_inside = fat_.size() == n;  // a new body count (e.g. periodic images) cannot be served
  for (std::size_t i = 0; all_inside && i < n; ++i) all_inside = inside(boxes[i], fat_[i]);
  if (!all_inside) {
    listed_ = false;
    if (served_ == 0) back_off();  // out at once: margins do not pay at this motion per frame
    return false;
  }
  ++served_;
  next_backoff_ = 1;
  out.clear();
  for (const BodyPair& p : list_)
    if (boxes[p.a].overlaps(boxes[p.b])) out.push_back(p);
  box_tests = list_.size();
  return true;
}

std::span<const Aabb> VerletList::fat_boxes(std::span<const Aabb> boxes) {
  const std::size_t n = boxes.size();
  fattened_ = false;
  if (reuse_ == 0) return boxes;
  const bool anchored = anchor_.size() == n && anchor_frames_ > 0;
  if (backoff_ > 0) {
    // Plain boxes. Anchors only for the frame before the next grown build, which measures
    // one frame of motion from them (no copy of every box on every plain frame).
    if (--backoff_ > 0) {
      anchor_.clear();
      return boxes;
    }
  } else {
    fat_.resize(n);
    const double frames = anchored ? static_cast<double>(anchor_frames_) : 1.0;
    bool short_lived = false;  // some body would leave its grown box within two frames
    for (std::size_t i = 0; i < n; ++i) {
      const Aabb& b = boxes[i];
      const double extent = largest_extent(b);
      const double per_frame = anchored ? face_motion(b, anchor_[i]) / frames : 0.0;
      double m = anchored ? std::min(reuse_ * per_frame, 0.25 * extent) : extent / 64.0;
      if (!(m >= 0.0) || !std::isfinite(m)) m = 0.0;
      if (m < 2.0 * per_frame) short_lived = true;
      Aabb f{b.lo.array() - m, b.hi.array() + m};
      if (!f.lo.allFinite() || !f.hi.allFinite()) f = b;
      fat_[i] = f;
    }
    if (short_lived)
      back_off();
    else
      fattened_ = true;
  }
  anchor_.assign(boxes.begin(), boxes.end());
  anchor_frames_ = 0;
  return fattened_ ? std::span<const Aabb>(fat_) : boxes;
}

void VerletList::back_off() {
  backoff_ = next_backoff_;
  next_backoff_ = std::min(2 * next_backoff_, kMaxBackoff);
}

std::uint64_t VerletList::adopt(std::span<const Aabb> boxes, std::vector<BodyPair>& found, std::vector<BodyPair>& out) {
  if (!fattened_) {
    out.swap(found);
    listed_ = false;
    return 0;
  }
  list_.swap(found);
  listed_ = true;
  served_ = 0;
  out.clear();
  for (const BodyPair& p : list_)
    if (boxes[p.a].overlaps(boxes[p.b])) out.push_back(p);
  return list_.size();
}

}  // namespace ccd::detail
