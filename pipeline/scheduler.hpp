#pragma once
// A scheduler drives the stages of collision detection over a whole horizon [0, T]: which
// bounds are built over which windows, which pairs are tested when, and over which interval
// each narrow call runs. Two implementations, built by the registry's factory from a method
// string (pipeline/scheduler_registry.hpp):
//   FixedStepScheduler  fixed steps of dt, one StepPipeline::run each
//                       (pipeline/fixed_step_scheduler.hpp);
//   EarliestScheduler   Hubbard's earliest-contact scheduling, per-body windows of at most dt
//                       (pipeline/earliest_scheduler.hpp).
// A run reports every contact with the interval [from, to] of the narrow call that found it
// (a fixed step's [t0, t1]; the sample time t0 == t1 for an instant bound), the stages'
// counts and times. Callers (the runner, Python through it, the benchmarks) match contacts to
// a truth and time the run; they never drive steps themselves.
// Virtual calls: one per run (and one per step or per run for the contact sink); none per
// pair.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/narrow/contact_result.hpp>
#include <pipeline/pair_counts.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/scene/scenery.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ccd {

struct ScheduledContact {
  BodyPair pair;
  ContactResult contact;  ///< Hit or Overlapping: first contact in [from, to]
  double from = 0.0;      ///< the narrow call's interval
  double to = 0.0;
};

/// A body's contact with a static polygon, found by a narrow call over [from, to].
struct ScheduledStaticContact {
  StaticPair pair;
  ContactResult contact;  ///< Hit or Overlapping: first contact in [from, to]
  double from = 0.0;
  double to = 0.0;
};

/// A run's counts. Fixed steps: every candidate is one pair check and every passed pair one
/// narrow call (less the static pairs the kinematic principle skipped); `batches` counts the
/// steps and `refreshes` bodies x steps.
struct ScheduleStats {
  /// The body pairs: broad-phase pairs summed over updates; bound pair tests (Bound::test
  /// calls, refinements whose refined boxes are disjoint, and speed re-checks); of those,
  /// Possible; narrow-phase calls. tests_saved stays 0.
  PairCounts bodies;
  /// The body-polygon pairs (0 without scenery): the static index's pairs; static tests
  /// (Bound::test_static calls, speed re-checks); of those, Possible; body-polygon narrow
  /// calls; fixed steps, kinematic: passed pairs not solved.
  PairCounts scenery;
  std::uint64_t rechecks = 0;   ///< of bodies.checks, speed re-checks (ScheduleOptions::recheck)
  std::uint64_t refreshes = 0;  ///< body bounds built (the first one of every body, the pair
                                ///< refinements' and the static refinements' (1 each) included)
  std::uint64_t batches = 0;    ///< distinct refresh events (times at which bounds were rebuilt)
  // Fixed steps only (0 and empty otherwise).
  std::uint64_t rebuilds = 0;  ///< steps at which the broad phase built its structure from scratch
  std::map<std::string, std::uint64_t, std::less<>> counters;  ///< the broad phase's own, summed over steps
};

/// Receives a run's contacts as they are found: a fixed-step run hands over each step's, the
/// earliest scheduler all of them at the end, each in the order the narrow calls ran.
class ContactSink {
 public:
  virtual ~ContactSink() = default;
  virtual void found(std::span<const ScheduledContact> contacts,
                     std::span<const ScheduledStaticContact> static_contacts) = 0;
};

struct ScheduleInput {
  /// Required: the scene's motion (centres, shapes, spin; ccd/motion/rigid_motion.hpp).
  const RigidMotion* motion = nullptr;
  double horizon = 0.0;             ///< T: the run covers [0, T]
  double acceleration_bound = 0.0;  ///< A given to Bounded bounds
  std::optional<WallBox> walls;
  bool timed = true;                          ///< read the clock per stage (ScheduleResult::times)
  const std::atomic<bool>* cancel = nullptr;  ///< checked once per step (or every 1024 events)
  /// Null: the contacts stay in ScheduleResult; otherwise they go here (and not there).
  ContactSink* sink = nullptr;
};

struct ScheduleResult {
  std::vector<ScheduledContact> contacts;  ///< without a sink, in the order the narrow calls ran
  std::vector<ScheduledStaticContact> static_contacts;
  ScheduleStats stats;
  StepTimes times;                 ///< stage seconds (with ScheduleInput::timed)
  double first_broad_seconds = 0;  ///< fixed steps: the broad phase at the first step
  bool finished = true;            ///< false: cancelled
};

class Scheduler {
 public:
  virtual ~Scheduler() = default;
  /// The scenery the bodies are checked against (indexed here; the polygons must outlive the
  /// scheduler). Empty: no static checks.
  virtual void set_scenery(std::span<const StaticPolygon> polygons) = 0;
  /// Runs over [0, in.horizon]; `out` is overwritten. Returns out.finished (false: stopped
  /// early because *in.cancel became true).
  virtual bool run(const ScheduleInput& in, ScheduleResult& out) = 0;
};

}  // namespace ccd
