// The earliest scheduler's body windows: how long a body's window is, where it ends, and the
// refresh of a batch of bodies over their next windows (bounds, broad-phase update, tests).
#include <pipeline/earliest_run.hpp>

#include <algorithm>

namespace ccd::earliest {

// The length of body i's window from its state (set at its start): dt, or with `reach` the
// longest dt / 2^k over which it moves at most reach x the mean radius (WindowPolicy).
double EarliestRun::window_length(std::uint32_t i) const { return window_policy().length(states_[i].velocity); }

// The end of body i's window starting at t.
double EarliestRun::window_end(std::uint32_t i, double t) const { return window_policy().end(window_length(i), t); }

WindowPolicy EarliestRun::window_policy() const {
  return {dt_, T_, in_.acceleration_bound, reach_length_, s_.options.align};
}

// Rebuilds the bounds of `batch_` (states set) from t, each over its own window, one
// Bound::refresh per distinct window end; sorts `batch_` by (end, body) when ends differ.
void EarliestRun::build_windows(double t) {
  bool same = true;
  for (const std::uint32_t i : batch_) {
    ends_[i] = window_end(i, t);
    same = same && ends_[i] == ends_[batch_.front()];
  }
  ctx_.t0 = t;
  ctx_.start = states_;
  if (!same)
    std::sort(batch_.begin(), batch_.end(),
              [&](std::uint32_t x, std::uint32_t y) { return ends_[x] != ends_[y] ? ends_[x] < ends_[y] : x < y; });
  for (std::size_t b = 0; b < batch_.size();) {
    std::size_t e = b + 1;
    while (e < batch_.size() && ends_[batch_[e]] == ends_[batch_[b]]) ++e;
    group_.assign(batch_.begin() + static_cast<std::ptrdiff_t>(b), batch_.begin() + static_cast<std::ptrdiff_t>(e));
    ctx_.t1 = ends_[batch_[b]];
    s_.bound.refresh(ctx_, group_, boxes_);
    b = e;
  }
}

void EarliestRun::queue_expiry(std::uint32_t i, double w1) {
  if (w1 < T_) queue_.push({w1, Kind::Expiry, i, i, version_[i], version_[i], w1});
}

// Refreshes the bodies of `batch_` at time t over their next windows: bounds, a new version
// and expiry each, the broad phase's update, the tests of the pairs it reports.
void EarliestRun::refresh(double t) {
  ++stats_.batches;
  stats_.refreshes += batch_.size();
  watch_.start();
  for (const std::uint32_t i : batch_) state_at(i, t);
  build_windows(t);
  watch_.stop(local_.bound);
  for (const std::uint32_t i : batch_) {
    version_[i] = ++stamp_;
    queue_expiry(i, ends_[i]);
  }
  watch_.start();
  s_.broad.update(boxes_, batch_, pairs_);
  watch_.stop(local_.broad);
  stats_.bodies.candidates += pairs_.size();
  watch_.start();
  test_pairs(t);
  watch_.stop(local_.bound);
  test_static_pairs(t, batch_);
}

}  // namespace ccd::earliest
