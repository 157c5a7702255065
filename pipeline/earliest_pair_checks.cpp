// The earliest scheduler's pair-check policy: the bound tests of the pairs a refresh
// reports, and a due check's decision: a speed re-check (`recheck`), a refinement of stale
// bounds (`stale`), or the narrow phase; the narrow calls, and the rounds in which inline
// checks run.
#include <pipeline/earliest_run.hpp>

#include <bounds/speed_earliest.hpp>

#include <algorithm>
#include <limits>

namespace ccd::earliest {

// Tests the reported pairs and queues a check for each that may touch (not before now).
void EarliestRun::test_pairs(double now) {
  if (inline_checks_) pending_.reserve(pending_.size() + (wrapped_ ? image_pairs_.size() : pairs_.size()));
  // One pair: x and y are the slots checked (bodies, or images when the scene wraps around),
  // a and b the bodies whose versions date the check.
  const auto test = [&](std::uint32_t x, std::uint32_t y, std::uint32_t a, std::uint32_t b) {
    ++stats_.bodies.checks;
    const PairTest r = s_.bound.test(std::min(x, y), std::max(x, y));
    if (!r.possible()) return;
    ++stats_.bodies.passed;
    const Window w = common_window(s_.bound.window(x), s_.bound.window(y));
    const double t = std::max(r.earliest, now);
    if (inline_checks_) pending_.push_back({t, x, y, w.t0, w.t1});
    else queue_.push({t, Kind::Check, x, y, version_[a], version_[b], w.t0});
  };
  if (wrapped_) {
    for (const ImagePair& q : image_pairs_) test(q.x, q.y, q.a, q.b);
    return;
  }
  for (const BodyPair& p : pairs_) test(p.a, p.b, p.a, p.b);
}

// A speed re-check from both bodies' states at c.t (no bound built), then the narrow phase
// from its earliest time over one chunk; the pair comes back at the chunk's end.
void EarliestRun::recheck_pair(const Check& c) {
  const double to = c.to;
  state_at(c.a, c.t);
  state_at(c.b, c.t);
  const SpeedBall ba{states_[c.a].position, c.t, speed_bound(c.a, c.t, to), states_[c.a].radius};
  const SpeedBall bb{states_[c.b].position, c.t, speed_bound(c.b, c.t, to), states_[c.b].radius};
  const double from = std::max(c.t, speed_earliest(ba, bb));
  ++stats_.bodies.checks;
  ++stats_.rechecks;
  if (from > to) return;  // no contact possible in the rest of the common window
  ++stats_.bodies.passed;
  // The chunk: the time in which the pair's distance may change by `chunk` x the sum of
  // their radii (at least the rest of the window when neither may move).
  const double closing = ba.speed + bb.speed;
  const double h = s_.options.chunk > 0.0 && closing > 0.0 ? s_.options.chunk * (ba.radius + bb.radius) / closing
                                                            : std::numeric_limits<double>::infinity();
  if (from < to && from >= c.t + h) {  // far enough: look again when they may touch
    next_.push_back({from, c.a, c.b, c.since, to});
    return;
  }
  jobs_.push_back({c.a, c.b, from, from + h < to ? from + h : to, to});
}

// Hubbard's refinement: the pair's own bounds from c.t to the end of the common window, in
// the scratch instance, and the pair tested again (a later check, or none).
void EarliestRun::refine_pair(const Check& c) {
  const double to = c.to;
  state_at(c.a, c.t);
  state_at(c.b, c.t);
  PairTest r;
  if (wrapped_) {  // the two slots' paths as bodies 0 and 1 of the scratch instance
    static constexpr std::uint32_t kPairIds[2] = {0, 1};
    pair_states_[0] = states_[c.a];
    pair_states_[1] = states_[c.b];
    const Trajectories& pv = images_.pair_view(c.a, c.b, c.t, to);
    pair_motion_.assign_spheres(pv);  // a wrapped run has plain spheres only
    StepContext pc = ctx_;
    pc.motion = &pair_motion_;
    pc.t0 = c.t;
    pc.t1 = to;
    pc.start = pair_states_;
    pc.exact = s_.knowledge == Knowledge::Exact ? &pv : nullptr;
    if (scratch_boxes_.size() < 2) scratch_boxes_.resize(2);
    s_.scratch.refresh(pc, kPairIds, scratch_boxes_);
    // Disjoint boxes: the bounds inside them are too (no bound test needed).
    if (scratch_boxes_[0].overlaps(scratch_boxes_[1])) r = s_.scratch.test(0, 1);
  } else {
    pair_bodies_[0] = c.a;
    pair_bodies_[1] = c.b;
    ctx_.t0 = c.t;
    ctx_.t1 = to;
    ctx_.start = states_;
    if (scratch_boxes_.size() != n_) scratch_boxes_.resize(n_);
    s_.scratch.refresh(ctx_, pair_bodies_, scratch_boxes_);
    if (scratch_boxes_[c.a].overlaps(scratch_boxes_[c.b])) r = s_.scratch.test(c.a, c.b);
  }
  stats_.refreshes += 2;
  ++stats_.bodies.checks;
  if (r.possible()) {
    ++stats_.bodies.passed;
    next_.push_back({std::max(r.earliest, c.t), c.a, c.b, c.t, to});
  }
}

// A due check at c.t (inline mode; c.a, c.b slots when wrapped): the speed re-check or the
// refinement, which give a later check (into `next_`), a narrow call (into `jobs_`) or
// nothing. Reads only the two bodies' bounds and motion, which no refresh changes before
// the check is due (both windows end at or after c.t).
void EarliestRun::decide(const Check& c) {
  if (is_static(c.b)) decide_static(c);
  else if (s_.options.recheck) recheck_pair(c);
  else if (refine_ && c.t - c.since > stale_age_) refine_pair(c);
  else jobs_.push_back({c.a, c.b, c.t, c.to, c.to});
}

// The narrow phase of a check's pair (wrapped: the two slots' paths) over [from, until].
ContactResult EarliestRun::narrow_pair(std::uint32_t x, std::uint32_t y, double from, double until) {
  if (wrapped_) {  // plain spheres only: the sphere x sphere entry
    pair_states_[0] = states_[x];
    pair_states_[1] = states_[y];
    pair_motion_.assign_spheres(images_.pair_view(x, y, from, until));
    const NarrowInput in{&pair_motion_, pair_states_, {}, from, until, false};
    return s_.narrow(in, 0, 1);
  }
  const NarrowInput in{in_.motion, states_, {}, from, until, false};
  return spheres_ ? s_.narrow(in, x, y) : s_.table.find(in_.motion->kind(x), in_.motion->kind(y))(in, x, y);
}

// A narrow call over [from, until]; a found contact is reported over [from, to] and ends
// the pair's window (as one call over [from, to] would have found it first), else a chunk
// short of the window's end brings the pair back at its end (into `next_`). The same for
// a static check's (body, polygon) pair and the body's window.
void EarliestRun::narrow_job(const Job& j) {
  if (is_static(j.b)) {
    const ContactResult c = narrow_static(j.a, polygon_of(j.b), j.from, j.until);
    if (c.found()) static_contacts_.push_back({{j.a, polygon_of(j.b)}, c, j.from, j.to});
    else if (j.until < j.to) next_.push_back({j.until, j.a, j.b, j.from, j.to});
    return;
  }
  ++stats_.bodies.narrow_calls;
  const ContactResult c = narrow_pair(j.a, j.b, j.from, j.until);
  if (c.found()) contacts_.push_back({{owner(j.a), owner(j.b)}, c, j.from, j.to});
  else if (j.until < j.to) next_.push_back({j.until, j.a, j.b, j.from, j.to});  // a re-check (reads no `since`)
}

// One round of inline checks: every pending check decided (bound time), then the round's
// narrow calls (narrow time); what they give is the next round. Two clock reads a stage
// per round, not per check.
void EarliestRun::drain_round() {
  jobs_.clear();
  jobs_.reserve(pending_.size());
  next_.reserve(pending_.size());
  watch_.start();
  for (const Check& c : pending_) decide(c);
  watch_.stop(local_.bound);
  watch_.start();
  for (const Job& j : jobs_) narrow_job(j);
  watch_.stop(local_.narrow);
  pending_.swap(next_);
  next_.clear();
}

}  // namespace ccd::earliest
