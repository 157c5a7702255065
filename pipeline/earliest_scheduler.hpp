#pragma once
// Hubbard's earliest-contact scheduling (Hubbard 1995; Mirtich's Timewarp; kinetic sweep
// and prune): the `earliest` scheduler of pipeline/scheduler_registry.hpp. A pair is
// looked at again only at the earliest time its bounds allow contact, so far-apart pairs
// cost nothing for many windows.
//
// State: every body i has a bound over its own window [w0_i, w1_i] (w1_i = min(w0_i + w_i,
// T), or with `align` the next multiple of w_i after w0_i; w_i = dt, or with `reach` a
// speed-adapted dt / 2^k), built from its state at w0_i
// (Bound::refresh), and its box in the broad phase. Two kinds of events, in time order
// (pair checks before expiries at equal times; see below for when checks skip the queue):
//  - expiry of body i at w1_i: all bodies expiring at that time refresh their bounds over
//    their next windows, the broad phase updates only those (BroadPhase::update), and
//    every pair it reports is tested (Bound::test over the common part of both windows);
//    a pair that may touch gets a check at its `earliest`;
//  - check of pair (a, b) at t: when the bounds the check came from are older than
//    `stale` x dt, they are first rebuilt at t (Hubbard's refinement: a fresh bound is
//    tight near t) and the pair re-tested (the pair's own refined boxes first: disjoint
//    boxes hold disjoint bounds), which gives a later check or none; otherwise
//    the narrow phase runs from t to the end of the common window. The refinement builds
//    the pair's own bounds from t to the end of the common window in a second instance of
//    the bound (default: nothing else changes), or, with `refresh_bodies`, refreshes the
//    two bodies' bounds themselves (their windows then start at t, every pair of theirs is
//    re-tested, and windows of different bodies differ). Every refresh of a body bumps its
//    version, so queued checks made from its old bound are dropped when they come up.
// Coverage (why nothing is missed while the bound's assumption holds): each pair's time is
// tiled by the common windows of its bodies' bounds; each common window is examined when
// its later-starting bound is built (broad phase, then pair test), no contact is possible
// in it before the test's `earliest`, and from there the narrow phase covers the rest of
// it, or a refinement covers the rest of it from the check time on. A refinement advances
// the age of the pair's bounds by at least stale x dt, so a pair is refined at most
// T / (stale dt) times.
// With `recheck` a due check at t is re-checked instead of refined: from both bodies'
// states at t and speed bounds over [t, w1] (w1 the common window's end; the exact pieces'
// largest speed, or |v(t)| + A (w1 - t) for a bound that knows only A), no contact is
// possible before e = t + gap / (s_a + s_b) (bounds/speed_earliest.hpp). A later e (a
// chunk or more ahead) re-queues the check at e; otherwise the narrow phase covers
// [e, min(e + h, w1)], h = chunk x (r_a + r_b) / (s_a + s_b), and the pair comes back at
// its end. Time moves on by at least h per check, so a pair costs at most (w1 - t) / h + 1
// narrow calls per window, and no bound is built beyond one per body and window.
// Coverage then tiles the common window with [t, e) (no contact possible) and narrow
// chunks. A found contact ends the pair's window (reported over [e, w1], as one narrow
// call from e to w1 would have found it).
// Checks run as soon as they are made unless a refinement may refresh bodies
// (`refresh_bodies` without `recheck`): a check made when a body's bound is built is due
// before either body's window ends, and nothing it reads (the two bodies' bounds and
// motion) changes before then, so running it at once gives what running it at its time
// would. The checks a refresh makes run in rounds (every check decided, then the round's
// narrow calls, then the checks those give), which takes stage times per round, not per
// check; the priority queue then holds only the expiries. With refinements that refresh
// bodies, checks are queued in time order as events.
// Contacts are reported with the narrow call's interval [from, to]: the runner credits
// the events of the pair that start in it (as a fixed step credits the events that start
// in the step).
// Scenes that wrap around (motion.periodic(), docs/periodic.md): the bound and the broad
// phase work on slots (pipeline/scheduler_images.hpp): body i's home slot i (its path
// unwrapped over its window) and one slot per image of the home's box that meets the cell,
// built at every refresh of the body (the homes' bounds first, then the images'); slots of
// images that no longer meet the cell return to a pool, their boxes parked where they meet
// nothing. A slot pair reported by the broad phase is the image pair (a, b, relative
// shift); pairs of one body's own slots are dropped and each image pair is tested once per
// refresh. Checks are queued per slot pair; the narrow phase and a pair's own bounds run on
// the two slots' paths (the shift built in), and a contact is reported for the bodies. A
// slot changes hands only when its body refreshes, which makes its queued checks stale, so
// coverage is as above for every image pair. `refreshes` counts image bounds too.
// Static scenery (set_scenery; docs/scenery-methods.md): the polygons are indexed once in a
// StaticIndex (ccd/broad_phase/static_index.hpp). Whenever a body's bound is built over a
// window (the first one and every refresh), the index is queried with the body's box and
// each (body, polygon) pair it reports is tested with Bound::test_static over that body's
// own window; a pair that may touch gets a static check at its `earliest`, handled as a
// pair check with one body: the same `stale` refinement (the body's own bound rebuilt from
// the check time to its window's end in the scratch instance, then test_static again),
// speed re-check with `recheck` (the body's speed bound and its distance to the polygon,
// a chunk being the time in which that distance may change by chunk x r), or narrow phase
// (the narrow table's polygon column by the body's kind, ccd/narrow/narrow_table.hpp: exact
// for spheres, conservative advancement for other shapes) from the check time to the window's end. With `refresh_bodies` (queued
// checks) a stale static check refreshes its body. Coverage: each body's time is tiled by
// its windows, each window's polygons are examined when its bound is built, as above.
// A scene that wraps around takes no scenery (std::invalid_argument).
#include <bounds/bound.hpp>
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/broad_phase/static_index.hpp>
#include <ccd/narrow/narrow_table.hpp>
#include <pipeline/scheduler.hpp>
#include <pipeline/step_pipeline.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace ccd {

struct ScheduleOptions {
  double window = 0.0;  ///< dt: the longest window a bound covers (seconds, > 0)
  double stale = 0.25;  ///< refinement threshold, a fraction of dt in (0, 1]; 1: never refine
  /// true: a window refreshed at t ends at the next multiple of dt after t (so bodies
  /// refined at different times still expire together and the broad phase updates them
  /// in one batch); false: at t + dt (every body on its own clock).
  bool align = true;
  /// > 0: speed-adapted windows. A body's window is the longest dt / 2^k (k <= 10) over
  /// which it moves at most `reach` x the bodies' mean radius, judged from its state at the
  /// window start (|v| w + A w^2 / 2); with `align` it ends on a multiple of its own length,
  /// so bodies of one length still expire together. Slow bodies keep long windows (few
  /// refreshes), fast ones get short, tight ones (few candidates), and the broad phase
  /// updates only the bodies that expire. A choice of windows only: coverage (below) holds
  /// for any windows. 0: every window is dt long.
  double reach = 0.0;
  /// false: a refinement builds the pair's own bounds (a second bound instance); true: it
  /// refreshes the two bodies' bounds, with a broad-phase update and a re-test of their pairs.
  bool refresh_bodies = false;
  /// true: a due pair check is first re-checked from both bodies' states at the check time
  /// with speed bounds over the rest of the common window (bounds/speed_earliest.hpp; no
  /// bound is built, `stale` and `refresh_bodies` are not used); the narrow phase then runs
  /// from that earliest time over one chunk (below), and the pair is re-checked at the
  /// chunk's end; an earliest time a chunk or more ahead re-queues the check there instead.
  bool recheck = false;
  /// With `recheck`: a chunk is the time in which the pair's distance may change by
  /// chunk x (r_a + r_b) at the speed bounds; 0: the rest of the common window.
  double chunk = 2.0;
};

class EarliestScheduler final : public Scheduler {
 public:
  /// `bound` and `scratch` are two instances of the same bound (`scratch` holds the pairs'
  /// refined bounds); `knowledge` is theirs; an Instant bound has no window
  /// (std::invalid_argument).
  EarliestScheduler(std::unique_ptr<Bound> bound, std::unique_ptr<Bound> scratch, Knowledge knowledge,
                    std::unique_ptr<BroadPhase> broad, ScheduleOptions options,
                    const NarrowTable& table = narrow_table());

  /// Runs over [0, in.horizon] (Scheduler::run); the contacts are in the order the narrow
  /// calls ran (a pair's contacts in time order). A scene that wraps around
  /// (periodic centres) takes plain spheres only (std::invalid_argument unless
  /// in.motion->spheres()) and
  /// no scenery. The run itself is pipeline/earliest_run.hpp.
  bool run(const ScheduleInput& in, ScheduleResult& out) override;

  /// The scenery the bodies are checked against (indexed here; the polygons must outlive
  /// the scheduler). Empty: no static checks.
  void set_scenery(std::span<const StaticPolygon> polygons) override;

  const Bound& bound() const { return *bound_; }

 private:
  std::unique_ptr<Bound> bound_;
  std::unique_ptr<Bound> scratch_;
  Knowledge knowledge_;
  std::unique_ptr<BroadPhase> broad_;
  ScheduleOptions options_;
  NarrowEntry narrow_;
  const NarrowTable* table_;
  std::span<const StaticPolygon> scenery_;
  StaticIndex static_index_;
};

}  // namespace ccd
