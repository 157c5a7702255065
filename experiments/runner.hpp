#pragma once
// Runs one method at one timestep over a scene and measures it against exact ground
// truth (definitions in docs/experiments.md). The method's scheduler runs over the horizon
// (pipeline/scheduler.hpp, built by the registry's factory); this file only counts, times
// and matches:
//  - samples t_k = k * dt (the product in double, never accumulated), every k >= 0 with
//    t_k <= T (sample_count; fixed steps: pipeline/fixed_step_scheduler.hpp);
//  - a discrete method (an Instant bound) checks overlap at each sample: an event is
//    detected if the method confirms the pair at some t_k in [enter, exit], else missed;
//  - a continuous method checks each step [t_k, t_{k+1}] (and the last partial step): an
//    event is detected when the pair is confirmed by the exact narrow phase in a step
//    that contains its enter time;
//  - a scheduled method (BOUND/BROADPHASE@earliest) runs the earliest scheduler over the
//    whole horizon with windows of at most dt (pipeline/earliest_scheduler.hpp): an
//    event is detected when the pair is confirmed by a narrow call whose interval
//    contains its enter time.
#include "method.hpp"
#include "truth_index.hpp"

#include <ccd/motion/rigid_motion.hpp>

#include <ccd/motion/trajectory.hpp>
#include <pipeline/fixed_step_scheduler.hpp>
#include <pipeline/pair_counts.hpp>
#include <ccd/scene/scene.hpp>
#include <ccd/truth/static_truth.hpp>
#include <ccd/truth/truth_io.hpp>

#include <atomic>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ccdlab {

struct RunInput {
  const ccd::Scene* scene = nullptr;
  /// Required: the scene's motion (centres, shapes, spin; ccd/motion/rigid_motion.hpp), the
  /// one every stage of the method takes.
  const ccd::RigidMotion* motion = nullptr;
  const TruthIndex* truth = nullptr;
  /// The truth's body-static events (ccd/truth/static_truth.hpp); empty without scenery.
  std::span<const ccd::StaticEvent> static_events;
  /// Seconds: the truth's largest certified error (enter_error, exit_error), widening the
  /// window in which a detection is matched to an event; 0 for an exact truth.
  double truth_error = 0.0;
  /// One entry per truth event (static event), or empty when every one is exact: events
  /// flagged `undecided` are counted apart (PairRecord::undecided), never detected or missed.
  std::span<const ccd::EventError> errors;
  std::span<const ccd::EventError> static_errors;
  double acceleration_bound = 0.0;          ///< A given to Bounded bounds
  int repeats = 1;                          ///< timing repeats; times are medians
  const std::atomic<bool>* cancel = nullptr;  ///< checked once per step
  bool list_missed = false;                 ///< fill PairRecord::missed_events
};

/// A ground-truth event the method missed (PairRecord::missed_events).
struct MissedEvent {
  std::uint32_t a = 0, b = 0;
  double enter = 0.0, exit = 0.0;
};

/// One kind of pair in a run (RunRecord::bodies, RunRecord::scenery): the stages' counts
/// summed over steps (ccd::PairCounts: candidates, checks = the bound's pair tests, passed =
/// the bound candidates, narrow calls, tests saved by the kinematic principle) and the
/// truth's events counted against the contacts found.
struct PairRecord : ccd::PairCounts {
  std::uint64_t events = 0;            ///< ground-truth events, all of them
  std::uint64_t initial_contacts = 0;  ///< of those, events in progress at t = 0 (enter == 0)
  std::uint64_t detected = 0;          ///< of the other events, those detected
  std::uint64_t missed = 0;            ///< of the other events, those missed
  /// Of the events, those the truth could not decide (ccd::EventError::undecided): counted
  /// apart, neither detected nor missed, and outside initial_contacts.
  std::uint64_t undecided = 0;
  std::uint64_t confirmed = 0;  ///< of the bound candidates, pairs the exact narrow phase confirmed
  /// With RunInput::list_missed: the events missed. Body pairs: sorted by enter (then a, b);
  /// scenery: a = body, b = polygon (an index into Scene::scenery), in the truth's order
  /// (enter, body, polygon).
  std::vector<MissedEvent> missed_events;
};

struct RunRecord {
  std::string method;
  std::string bound;
  std::string broad_phase;
  nlohmann::json options;      ///< what the method ran with: {"bound": {...}, "broad_phase": {...}}
  std::string knowledge;       ///< instant | exact | bounded
  bool continuous = false;
  /// The method's guarantee as it ran: continuous, a conservative bound, and for a bound
  /// that assumes |acceleration| <= A, an A no smaller than the scene's largest. Discrete
  /// methods never are (they see samples only).
  bool conservative = false;
  double dt = 0.0;
  double hz = 0.0;             ///< 1 / dt, or the frequency as the experiment gave it
  std::uint64_t steps = 0;     ///< samples (discrete) or steps (continuous)
  /// The body pairs: the truth's body-body events; the broad phase's pairs summed over
  /// steps, those passing the bound's own test, those the exact narrow phase confirmed.
  PairRecord bodies;
  /// The body-polygon pairs (0 for a scene without scenery): the truth's body-static events,
  /// counted like the body-body ones (in progress at t = 0 apart; detected by the same rule),
  /// the static stages' pairs summed over steps (scheduled methods: over the bodies' windows
  /// and the static refinements), and the static pairs the kinematic principle skipped.
  PairRecord scenery;
  std::uint64_t false_positives = 0;   ///< bound candidates with no contact at the sample/in the step
  double max_penetration = 0.0;        ///< largest -signed distance (narrow phase) at first detection
  double mean_penetration = 0.0;
  double mean_lag = 0.0;               ///< mean detection time - enter over detected events
  double max_lag = 0.0;
  double bound_seconds = 0.0;          ///< bound prepare + bound pair tests (median of repeats)
  double broad_seconds = 0.0;          ///< broad phase (median of repeats)
  double first_broad_seconds = 0.0;    ///< broad phase at the first step alone (sap: its initial sort)
  double narrow_seconds = 0.0;         ///< exact narrow phase (median of repeats)
  double total_seconds = 0.0;          ///< the whole run incl. state evaluation (median)
  double seconds_per_simulated_second = 0.0;
  /// The running thread's CPU time over the same span as total_seconds (median): the
  /// method's work without the time the thread waited for a core, so small runs compare
  /// on a loaded machine (ccd/util/thread_cpu_time.hpp).
  double cpu_seconds = 0.0;
  double cpu_seconds_per_simulated_second = 0.0;  ///< cpu_seconds / horizon
  /// The broad phase's own counters (ccd::BroadPhase::counters), each summed over steps,
  /// by name (e.g. sap's and sweep's "swaps"; none for grid).
  std::vector<std::pair<std::string, std::uint64_t>> counters;
  std::uint64_t rebuilds = 0;          ///< steps at which the broad phase built its structure from scratch
                                       ///< (every step for brute, grid, hgrid, rtree)
  /// Scheduled methods (their pairs' checks and narrow calls, and these, are written only
  /// for them): body bounds built (the first of each body included). `steps` is then the
  /// number of refresh events, `false_positives` the narrow calls that found nothing.
  bool scheduled = false;
  std::uint64_t refreshes = 0;
  std::uint64_t self_check_unexpected = 0;  ///< confirmed contacts that truth does not have
  std::uint64_t self_check_undetected = 0;  ///< discrete: events containing a sample but not detected
  bool counts_stable = true;           ///< identical counts over all repeats
  bool cancelled = false;
};

/// Number of samples t_k = k * dt (the double product) with t_k <= horizon: K + 1 where
/// K is the largest k with k * dt <= horizon. 0 when dt is not positive and finite.
using ccd::sample_count;

/// Runs `method` at timestep `dt`. Never throws for a valid input; a cancelled run
/// returns with `cancelled` set.
RunRecord run_method(const RunInput& in, const MethodSpec& method, double dt);

nlohmann::json to_json(const RunRecord& r, bool list_missed = false);

}  // namespace ccdlab
