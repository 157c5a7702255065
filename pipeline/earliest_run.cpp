#include <pipeline/earliest_run.hpp>

#include <bounds/speed_earliest.hpp>
#include <ccd/motion/state_cursor.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ccd::earliest {

EarliestRun::EarliestRun(const Setup& setup, const ScheduleInput& in, ScheduleResult& out)
    : s_(setup),
      in_(in),
      motion_(in.motion->centres()),
      stats_(out.stats),
      contacts_(out.contacts),
      static_contacts_(out.static_contacts),
      wrapped_(in.motion->centres().periodic() != nullptr),
      spheres_(in.motion->spheres()),
      n_(in.motion->size()),
      dt_(setup.options.window),
      T_(in.horizon),
      stale_age_(setup.options.stale * setup.options.window),
      refine_(setup.options.stale < 1.0),
      inline_checks_(!setup.options.refresh_bodies || setup.options.recheck),
      local_(out.times),
      watch_{in.timed},
      states_(in.motion->size()),
      version_(in.motion->size(), 0),
      ends_(in.motion->size(), 0.0),
      pair_states_(2) {
  if (wrapped_ && !in.motion->spheres())
    throw std::invalid_argument("the earliest scheduler takes plain spheres only in a scene that wraps around");
  if (wrapped_ && !s_.scenery.empty())
    throw std::invalid_argument("the earliest scheduler takes no scenery in a scene that wraps around");
  if (n_ >= kStaticBit) throw std::invalid_argument("the earliest scheduler takes fewer than 2^31 bodies");
  ctx_.acceleration_bound = in.acceleration_bound;
  ctx_.walls = in.walls;
  ctx_.exact = s_.knowledge == Knowledge::Exact ? &motion_ : nullptr;
  ctx_.motion = in.motion;
  if (wrapped_) {
    images_.begin(motion_);
    boxes_.resize(n_);
    if (ctx_.walls) {  // the slots' paths are unwrapped: no walls on a wrapped axis
      constexpr double kInf = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < 3; ++k)
        if (motion_.periodic()->wrap[k]) {
          ctx_.walls->min[static_cast<int>(k)] = -kInf;
          ctx_.walls->max[static_cast<int>(k)] = kInf;
          ctx_.walls->boundary[k] = Boundary::Reflect;
        }
    }
  }
  if (s_.options.reach > 0.0 && n_ > 0) {
    double radii = 0.0;
    for (std::uint32_t i = 0; i < n_; ++i) radii += motion_.radius(i);
    reach_length_ = s_.options.reach * radii / static_cast<double>(n_);
  }
}

void EarliestRun::state_at(std::uint32_t i, double t) {
  if (wrapped_) {
    states_[i] = images_.state(i, t);
    return;
  }
  const Piece& q = motion_.piece_at(i, t);  // one lookup for both
  states_[i] = BodyState{q.position(t), q.velocity(t), motion_.radius(i)};
}

// A bound on body i's speed over [t, t1] (state at t set), as the bound's knowledge
// allows: the exact pieces' largest speed, or |v(t)| + A (t1 - t) (walls keep the speed).
double EarliestRun::speed_bound(std::uint32_t i, double t, double t1) const {
  if (s_.knowledge == Knowledge::Exact) return max_speed(motion_, owner(i), t, t1);
  constexpr double eps = std::numeric_limits<double>::epsilon();
  return (states_[i].velocity.norm() + in_.acceleration_bound * (t1 - t)) * (1.0 + 8.0 * eps);
}

// Every body's first window [0, min(dt, T)] (shorter with speed-adapted windows).
void EarliestRun::first_windows() {
  if (wrapped_) {
    batch_.resize(n_);
    for (std::uint32_t i = 0; i < n_; ++i) batch_[i] = i;
    refresh_wrapped(0.0, true);
    return;
  }
  watch_.start();
  StateCursor(motion_).evaluate(0.0, states_);  // every body at 0: one pass, no piece search
  ctx_.t0 = 0.0;
  ctx_.t1 = std::min(dt_, T_);
  ctx_.start = states_;
  s_.bound.prepare(ctx_, boxes_);
  stats_.refreshes += n_;
  std::fill(ends_.begin(), ends_.end(), ctx_.t1);
  if (reach_length_ > 0.0) {  // bodies with shorter windows: rebuilt over those
    batch_.clear();
    for (std::uint32_t i = 0; i < n_; ++i)
      if (window_end(i, 0.0) != ctx_.t1) batch_.push_back(i);
    stats_.refreshes += batch_.size();
    if (!batch_.empty()) build_windows(0.0);
  }
  watch_.stop(local_.bound);
  ++stats_.batches;
  watch_.start();
  s_.broad.find_pairs(boxes_, pairs_);
  watch_.stop(local_.broad);
  stats_.bodies.candidates += pairs_.size();
  watch_.start();
  test_pairs(0.0);
  watch_.stop(local_.bound);
  if (!s_.scenery.empty()) {
    batch_.resize(n_);
    for (std::uint32_t i = 0; i < n_; ++i) batch_[i] = i;
    test_static_pairs(0.0, batch_);
  }
  for (std::uint32_t i = 0; i < n_; ++i) queue_expiry(i, ends_[i]);
}

// A queued check (refresh_bodies without recheck only): one event at a time, since its
// refinement refreshes bodies.
void EarliestRun::queued_check(const Event& e) {
  if (is_static(e.b)) {  // a static check: refresh a stale body, else the narrow phase
    if (version_[e.a] != e.va) return;
    const Window w = s_.bound.window(e.a);
    if (refine_ && e.t - w.t0 > stale_age_) {
      batch_.assign(1, e.a);
      refresh(e.t);
      return;
    }
    watch_.start();
    const ContactResult c = narrow_static(e.a, polygon_of(e.b), e.t, w.t1);
    watch_.stop(local_.narrow);
    if (c.found()) static_contacts_.push_back({{e.a, polygon_of(e.b)}, c, e.t, w.t1});
    return;
  }
  const std::uint32_t oa = owner(e.a), ob = owner(e.b);  // bodies (e.a, e.b: slots when wrapped)
  if (oa == SchedulerImages::kFree || ob == SchedulerImages::kFree || version_[oa] != e.va || version_[ob] != e.vb)
    return;  // queued from an older bound
  const Window wa = s_.bound.window(e.a);
  const Window wb = s_.bound.window(e.b);
  batch_.clear();
  if (refine_ && e.t - wa.t0 > stale_age_) batch_.push_back(oa);
  if (refine_ && e.t - wb.t0 > stale_age_) batch_.push_back(ob);
  if (!batch_.empty()) {
    if (wrapped_) refresh_wrapped(e.t, false);
    else refresh(e.t);
    return;
  }
  const double to = std::min(wa.t1, wb.t1);
  ++stats_.bodies.narrow_calls;
  watch_.start();
  const ContactResult c = narrow_pair(e.a, e.b, e.t, to);
  watch_.stop(local_.narrow);
  if (c.found()) contacts_.push_back({{oa, ob}, c, e.t, to});
}

bool EarliestRun::run() {
  first_windows();
  bool finished = true;
  std::uint64_t popped = 0;
  const std::atomic<bool>* cancel = in_.cancel;
  while (!queue_.empty() || !pending_.empty()) {
    if (!pending_.empty()) {  // the checks the last refresh made, in rounds
      if (cancel && cancel->load(std::memory_order_relaxed)) {
        finished = false;
        break;
      }
      drain_round();
      continue;
    }
    if (cancel && (++popped & 1023u) == 0 && cancel->load(std::memory_order_relaxed)) {
      finished = false;
      break;
    }
    const Event e = queue_.top();
    queue_.pop();
    if (e.kind == Kind::Check) {
      queued_check(e);
      continue;
    }
    if (version_[e.a] != e.va) continue;
    batch_.assign(1, e.a);  // every body expiring at e.t, refreshed as one batch
    while (!queue_.empty() && queue_.top().kind == Kind::Expiry && queue_.top().t == e.t) {
      const Event x = queue_.top();
      queue_.pop();
      if (version_[x.a] == x.va) batch_.push_back(x.a);
    }
    if (wrapped_) refresh_wrapped(e.t, false);
    else refresh(e.t);
  }
  return finished;
}

}  // namespace ccd::earliest
