#pragma once
// One run of the earliest scheduler (pipeline/earliest_scheduler.hpp, where the method
// and its coverage argument are described), internal to it. The run's state lives here; its
// parts are in their own files:
//   earliest_run.cpp            the first windows and the event loop (expiries, queued checks);
//   earliest_windows.cpp        body windows: lengths, ends, refreshes of a batch of bodies;
//   earliest_pair_checks.cpp    the pair-check policy: bound tests, refinement (stale) or
//                               speed re-check (recheck), narrow calls, rounds of checks;
//   earliest_image_slots.cpp    wrapped scenes: home and image slots, image pairs;
//   earliest_static_checks.cpp  scenery: static index queries, static checks, narrow calls.
#include <ccd/broad_phase/static_index.hpp>
#include <pipeline/earliest_events.hpp>
#include <pipeline/earliest_scheduler.hpp>
#include <pipeline/scheduler_images.hpp>
#include <pipeline/window_policy.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd::earliest {

// What a run reads of its scheduler.
struct Setup {
  Bound& bound;
  Bound& scratch;
  Knowledge knowledge;
  BroadPhase& broad;
  const ScheduleOptions& options;
  NarrowEntry narrow;  // sphere x sphere
  const NarrowTable& table;
  std::span<const StaticPolygon> scenery;
  const StaticIndex& static_index;
};

class EarliestRun {
 public:
  EarliestRun(const Setup& setup, const ScheduleInput& in, ScheduleResult& out);
  /// Runs over [0, T]; false when cancelled. Stage times go to `out.times` when timed.
  bool run();

 private:
  // earliest_run.cpp
  void first_windows();
  void queued_check(const Event& e);
  std::uint32_t owner(std::uint32_t x) const { return wrapped_ ? images_.owner(x) : x; }
  void state_at(std::uint32_t i, double t);
  double speed_bound(std::uint32_t i, double t, double t1) const;
  // earliest_windows.cpp
  double window_length(std::uint32_t i) const;
  double window_end(std::uint32_t i, double t) const;
  WindowPolicy window_policy() const;
  void build_windows(double t);
  void refresh(double t);
  void queue_expiry(std::uint32_t i, double w1);
  // earliest_image_slots.cpp
  void image_pairs_of();
  void build_slots(const std::vector<std::uint32_t>& slots, double t);
  void refresh_wrapped(double t, bool first);
  // earliest_pair_checks.cpp
  void test_pairs(double now);
  void decide(const Check& c);
  void recheck_pair(const Check& c);
  void refine_pair(const Check& c);
  ContactResult narrow_pair(std::uint32_t x, std::uint32_t y, double from, double until);
  void narrow_job(const Job& j);
  void drain_round();
  // earliest_static_checks.cpp
  void test_static_pairs(double now, std::span<const std::uint32_t> bodies);
  void decide_static(const Check& c);
  ContactResult narrow_static(std::uint32_t i, std::uint32_t polygon, double from, double until);

  const Setup& s_;
  const ScheduleInput& in_;
  const Trajectories& motion_;  // in_.motion's centres
  ScheduleStats& stats_;
  std::vector<ScheduledContact>& contacts_;
  std::vector<ScheduledStaticContact>& static_contacts_;
  const bool wrapped_;  // bodies and their images as slots (pipeline/scheduler_images.hpp)
  const bool spheres_;  // plain spheres (RigidMotion::spheres): one narrow entry for every pair
  const std::size_t n_;
  const double dt_, T_;
  const double stale_age_;
  const bool refine_;  // stale < 1 (1: never; a window may exceed dt by rounding)
  // Checks that nothing can invalidate before they are due (no refinement refreshes a
  // body) run as soon as they are made, in rounds: `pending_` the round's checks, `next_`
  // the checks they give, `jobs_` the round's narrow calls. Otherwise checks are queued.
  const bool inline_checks_;
  StepTimes& local_;  // the result's stage times (added to only when timed)
  Watch watch_;

  std::vector<BodyState> states_;  // per body (per slot in a wrapped scene)
  // Versions are stamps unique over all bodies and refreshes: a queued event is current while
  // its bodies' stamps are (a slot given to another body then never matches either).
  std::vector<std::uint64_t> version_;
  std::uint64_t stamp_ = 0;
  std::vector<Aabb> boxes_, scratch_boxes_;  // the scratch instance holds refined pairs only (sized at the first)
  std::uint32_t pair_bodies_[2] = {0, 0};
  std::vector<BodyPair> pairs_;
  std::vector<std::uint32_t> batch_;
  EventQueue queue_;
  std::vector<Check> pending_, next_;
  std::vector<Job> jobs_;
  StepContext ctx_;
  // Windows: speed-adapted lengths (reach), each body's window end, a group of equal ends.
  double reach_length_ = 0.0;
  std::vector<double> ends_;
  std::vector<std::uint32_t> group_;
  // Wrapped scenes: the slots, the reported slot pairs as image pairs (a < b, relative
  // shift), each once, and the slots a refresh touched.
  struct ImagePair {
    std::uint32_t a, b;  // bodies
    ImageShift shift;    // of y's image against x's
    std::uint32_t x, y;  // slots (owners a and b)
  };
  SchedulerImages images_;
  std::vector<BodyState> pair_states_;
  RigidMotion slot_motion_, pair_motion_;  // plain spheres over a view of slots, of two slots
  std::vector<ImagePair> image_pairs_;
  std::vector<std::uint32_t> image_slots_, freed_, moved_;
  // Scenery: the index's polygons for one box, and the (body, polygon) pairs of a refresh.
  std::vector<std::uint32_t> polygons_;
  std::vector<StaticPair> static_pairs_;
};

}  // namespace ccd::earliest
