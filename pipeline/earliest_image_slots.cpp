// The earliest scheduler in a scene that wraps around: each body's home slot and the slots
// of its images (pipeline/scheduler_images.hpp), refreshed together, and the slot pairs
// the broad phase reports as image pairs.
#include <pipeline/earliest_run.hpp>

#include <algorithm>
#include <tuple>

namespace ccd::earliest {

// The reported slot pairs as image pairs (a < b, relative shift), each once.
void EarliestRun::image_pairs_of() {
  image_pairs_.clear();
  for (const BodyPair& p : pairs_) {
    std::uint32_t x = p.a, y = p.b;
    std::uint32_t a = images_.owner(x), b = images_.owner(y);
    if (a == SchedulerImages::kFree || b == SchedulerImages::kFree || a == b) continue;
    if (a > b) {
      std::swap(a, b);
      std::swap(x, y);
    }
    image_pairs_.push_back({a, b, images_.relative(x, y), x, y});
  }
  const auto key = [](const ImagePair& q) { return std::tie(q.a, q.b, q.shift); };
  std::sort(image_pairs_.begin(), image_pairs_.end(), [&](const ImagePair& p, const ImagePair& q) {
    return key(p) != key(q) ? key(p) < key(q) : std::tie(p.x, p.y) < std::tie(q.x, q.y);
  });
  image_pairs_.erase(std::unique(image_pairs_.begin(), image_pairs_.end(),
                                 [&](const ImagePair& p, const ImagePair& q) { return key(p) == key(q); }),
                     image_pairs_.end());
}

// Builds the bounds of `slots` (sorted by their owners' window ends) from t, one
// Bound::refresh per distinct end, each over the slots' unwrapped paths.
void EarliestRun::build_slots(const std::vector<std::uint32_t>& slots, double t) {
  ctx_.t0 = t;
  for (std::size_t b = 0; b < slots.size();) {
    const double end = ends_[images_.owner(slots[b])];
    std::size_t e = b + 1;
    while (e < slots.size() && ends_[images_.owner(slots[e])] == end) ++e;
    group_.assign(slots.begin() + static_cast<std::ptrdiff_t>(b), slots.begin() + static_cast<std::ptrdiff_t>(e));
    ctx_.t1 = end;
    const Trajectories& view = images_.view(group_, t, end);
    slot_motion_.assign_spheres(view);  // a wrapped run has plain spheres only
    ctx_.motion = &slot_motion_;
    ctx_.exact = s_.knowledge == Knowledge::Exact ? &view : nullptr;
    ctx_.start = states_;
    s_.bound.refresh(ctx_, group_, boxes_);
    b = e;
  }
}

// Refreshes the bodies of `batch_` at time t: their home slots, then their images (from the
// homes' boxes), one Bound::refresh per distinct window end each; the broad phase updates
// the homes, the images and the slots given back to the pool (or, the first time, finds all
// pairs).
void EarliestRun::refresh_wrapped(double t, bool first) {
  ++stats_.batches;
  watch_.start();
  for (const std::uint32_t i : batch_) {
    images_.set_home(i, t);
    state_at(i, t);
    ends_[i] = window_end(i, t);
  }
  std::sort(batch_.begin(), batch_.end(),
            [&](std::uint32_t x, std::uint32_t y) { return ends_[x] != ends_[y] ? ends_[x] < ends_[y] : x < y; });
  build_slots(batch_, t);
  image_slots_.clear();
  freed_.clear();
  for (const std::uint32_t i : batch_) {
    const Aabb home = boxes_[i];  // a copy: set_images may grow `boxes_`
    images_.set_images(i, home, boxes_, image_slots_, freed_);
  }
  states_.resize(images_.size());
  for (const std::uint32_t s : image_slots_) state_at(s, t);
  build_slots(image_slots_, t);
  stats_.refreshes += batch_.size() + image_slots_.size();
  watch_.stop(local_.bound);
  for (const std::uint32_t i : batch_) {
    version_[i] = ++stamp_;
    queue_expiry(i, ends_[i]);
  }
  watch_.start();
  moved_.assign(batch_.begin(), batch_.end());
  moved_.insert(moved_.end(), image_slots_.begin(), image_slots_.end());
  moved_.insert(moved_.end(), freed_.begin(), freed_.end());
  const std::size_t active = batch_.size() + image_slots_.size();
  for (std::size_t k = 0; k < active; ++k) images_.keep_clear(boxes_[moved_[k]], boxes_, moved_);
  if (moved_.size() > active + freed_.size()) {  // pooled slots re-parked: each once
    std::sort(moved_.begin(), moved_.end());
    moved_.erase(std::unique(moved_.begin(), moved_.end()), moved_.end());
  }
  if (first) s_.broad.find_pairs(boxes_, pairs_);
  else s_.broad.update(boxes_, moved_, pairs_);
  watch_.stop(local_.broad);
  watch_.start();
  image_pairs_of();
  stats_.bodies.candidates += image_pairs_.size();
  test_pairs(t);
  watch_.stop(local_.bound);
}

}  // namespace ccd::earliest
