#include "runner.hpp"

#include <ccd/motion/state_cursor.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/pipeline/earliest_scheduler.hpp>
#include <ccd/pipeline/step_pipeline.hpp>
#include <ccd/util/thread_cpu_time.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace ccdlab {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Counts {
  std::uint64_t candidates = 0, bound_candidates = 0, confirmed = 0, false_positives = 0;
  std::map<std::string, std::uint64_t, std::less<>> counters;  // the broad phase's own, summed over steps
  std::uint64_t rebuilds = 0;  // steps at which the broad phase built its structure from scratch
  std::uint64_t unexpected = 0;
  std::uint64_t pair_checks = 0, narrow_calls = 0, refreshes = 0, steps = 0;  // scheduled methods
  double bound_s = 0, broad_s = 0, narrow_s = 0, total_s = 0;
  double cpu_s = 0;  // the calling thread's CPU time over the same span as total_s
  double first_broad_s = 0;  // the broad phase at the first step (sap: the initial sort)
  std::vector<double> lag, penetration;  // per event; NaN = not detected
  // Scenery: the static stages' pairs, summed over steps, and per static event its lag.
  std::uint64_t static_candidates = 0, static_bound_candidates = 0, static_confirmed = 0, static_tests_saved = 0;
  std::uint64_t static_pair_checks = 0, static_narrow_calls = 0;  // scheduled methods
  std::vector<double> static_lag;
  bool operator==(const Counts& o) const {
    auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
      if (x.size() != y.size()) return false;
      for (std::size_t i = 0; i < x.size(); ++i)
        if (std::isnan(x[i]) != std::isnan(y[i])) return false;
      return true;
    };
    return candidates == o.candidates && bound_candidates == o.bound_candidates && confirmed == o.confirmed &&
           false_positives == o.false_positives && unexpected == o.unexpected && counters == o.counters &&
           rebuilds == o.rebuilds && pair_checks == o.pair_checks && narrow_calls == o.narrow_calls &&
           refreshes == o.refreshes && steps == o.steps && same(lag, o.lag) &&
           static_candidates == o.static_candidates && static_bound_candidates == o.static_bound_candidates &&
           static_confirmed == o.static_confirmed && static_tests_saved == o.static_tests_saved &&
           static_pair_checks == o.static_pair_checks && static_narrow_calls == o.static_narrow_calls &&
           same(static_lag, o.static_lag);
  }
};

// Matches one confirmed contact of pair p, found by a narrow call over [t0, t1], with the
// truth. A contact's time is the sample time (discrete) or the first contact in [t0, t1]
// (continuous); its penetration is minus the narrow phase's signed distance.
void match_contact(const RunInput& in, bool continuous, ccd::BodyPair p, const ccd::ContactResult& contact, double t0,
                   double t1, Counts& c) {
  const TruthIndex& truth = *in.truth;
  // Times are matched with this slack: the truth is accurate to 1e-9 relative to T.
  // A certified (rigid) truth widens it by its largest error.
  const double slack = std::max(1e-9 * in.scene->horizon, in.truth_error);
  const double when = contact.toi;
  bool matched = false;
  for (std::uint32_t e : truth.of_pair(p.a, p.b)) {
    const ccd::ContactEvent& ev = truth.events()[e];
    if (ev.exit < t0 - slack || ev.enter > t1 + slack) continue;
    matched = true;
    // Continuous: detected when confirmed in a step that contains its enter time.
    // Discrete: detected at the first sample inside the event.
    if (continuous && ev.enter < t0 - slack) continue;
    if (std::isnan(c.lag[e])) {
      // A continuous method confirms the pair from its first contact in the step on;
      // an event that starts later in the same step (the pair was already touching
      // at the step's start from an earlier event) is detected at its own start, where
      // the same signed distance is evaluated.
      const double at = continuous ? std::max(when, ev.enter) : when;
      // Rigid pairs: the narrow phase's bound at its own time (the sphere formula would
      // measure the enclosing spheres).
      const bool spheres = !in.rigid || (in.rigid->kind(p.a) == ccd::ShapeKind::Sphere &&
                                         in.rigid->kind(p.b) == ccd::ShapeKind::Sphere);
      const double signed_distance = at == when || !spheres
                                         ? contact.signed_distance
                                         : ccd::sphere_signed_distance(*in.trajectories, p.a, p.b, at);
      c.lag[e] = std::max(0.0, at - ev.enter);
      c.penetration[e] = std::max(0.0, -signed_distance);
    }
  }
  if (!matched) ++c.unexpected;
}

// The static events of each (body, polygon) pair, by index into RunInput::static_events.
using StaticEventIndex = std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>>;

StaticEventIndex index_static_events(std::span<const ccd::StaticEvent> events) {
  StaticEventIndex index;
  for (std::uint32_t e = 0; e < events.size(); ++e) index[{events[e].body, events[e].polygon}].push_back(e);
  return index;
}

// Matches one static contact found by a narrow call over [t0, t1] with the truth's static
// events, by the rule of match_contact.
void match_static_contact(const RunInput& in, const StaticEventIndex& index, bool continuous,
                          const ccd::StaticContact& sc, double t0, double t1, Counts& c) {
  const double slack = std::max(1e-9 * in.scene->horizon, in.truth_error);
  const auto it = index.find({sc.pair.body, sc.pair.polygon});
  bool matched = false;
  if (it != index.end()) {
    for (const std::uint32_t e : it->second) {
      const ccd::StaticEvent& ev = in.static_events[e];
      if (ev.exit < t0 - slack || ev.enter > t1 + slack) continue;
      matched = true;
      if (continuous && ev.enter < t0 - slack) continue;
      if (std::isnan(c.static_lag[e])) {
        const double at = continuous ? std::max(sc.contact.toi, ev.enter) : sc.contact.toi;
        c.static_lag[e] = std::max(0.0, at - ev.enter);
      }
    }
  }
  if (!matched) ++c.unexpected;
}

// A scheduled method: the earliest scheduler over the whole horizon, windows of at most dt.
Counts run_scheduled_once(const RunInput& in, const MethodSpec& method, double dt, bool& cancelled) {
  const ccd::Trajectories& traj = *in.trajectories;
  Counts c;
  const std::size_t n_events = in.truth->events().size();
  c.lag.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.penetration.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.static_lag.assign(in.static_events.size(), std::numeric_limits<double>::quiet_NaN());
  ccd::ScheduleOptions options;
  options.window = dt;
  options.stale = method.scheduler.options.number("stale");
  options.align = method.scheduler.options.integer("align") != 0;
  options.refresh_bodies = method.scheduler.options.integer("refresh_bodies") != 0;
  options.reach = method.scheduler.options.number("reach");
  options.recheck = method.scheduler.options.integer("recheck") != 0;
  options.chunk = method.scheduler.options.number("chunk");
  options.rigid = in.rigid;
  ccd::EarliestScheduler scheduler(method.bound.make(), method.bound.make(), method.bound.info->knowledge,
                                   method.broad_phase.make(), options);
  scheduler.set_scenery(in.scene->scenery);
  std::vector<ccd::ScheduledContact> contacts;
  ccd::StepTimes times;
  const auto t_start = Clock::now();
  const double cpu_start = ccd::thread_cpu_seconds();
  cancelled = !scheduler.run(traj, in.scene->horizon, in.acceleration_bound, in.scene->box, contacts, &times, in.cancel);
  c.cpu_s = ccd::thread_cpu_seconds() - cpu_start;
  c.total_s = seconds_since(t_start);
  c.bound_s = times.bound;
  c.broad_s = times.broad;
  c.narrow_s = times.narrow;
  const ccd::ScheduleStats& st = scheduler.stats();
  c.candidates = st.candidates;
  c.bound_candidates = st.passed;
  c.confirmed = contacts.size();
  c.false_positives = st.narrow_calls - contacts.size();
  c.pair_checks = st.pair_checks;
  c.narrow_calls = st.narrow_calls;
  c.refreshes = st.refreshes;
  c.steps = st.batches;
  for (const ccd::ScheduledContact& sc : contacts) match_contact(in, true, sc.pair, sc.contact, sc.from, sc.to, c);
  c.static_candidates = st.static_candidates;
  c.static_bound_candidates = st.static_passed;
  c.static_confirmed = scheduler.static_contacts().size();
  c.static_pair_checks = st.static_checks;
  c.static_narrow_calls = st.static_narrow_calls;
  const StaticEventIndex static_index = index_static_events(in.static_events);
  for (const ccd::ScheduledStaticContact& sc : scheduler.static_contacts())
    match_static_contact(in, static_index, true, {sc.pair, sc.contact}, sc.from, sc.to, c);
  return c;
}

Counts run_once(const RunInput& in, const MethodSpec& method, double dt, bool& cancelled) {
  if (method.scheduled()) return run_scheduled_once(in, method, dt, cancelled);
  const ccd::Trajectories& traj = *in.trajectories;
  const TruthIndex& truth = *in.truth;
  const double T = in.scene->horizon;
  const bool continuous = method.continuous();

  ccd::PipelineOptions options;
  options.narrow_from_earliest = method.scheduler.options.integer("narrow_from_earliest") != 0;
  options.kinematic = method.scheduler.options.integer("kinematic") != 0;
  ccd::StepPipeline pipeline(method.bound.make(), method.bound.info->knowledge, method.broad_phase.make(),
                             ccd::narrow_table(), options);
  pipeline.set_scenery(in.scene->scenery);
  std::vector<ccd::BodyState> states;
  ccd::StepResult step;
  ccd::StateCursor cursor(traj);

  Counts c;
  const std::size_t n_events = truth.events().size();
  c.lag.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.penetration.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.static_lag.assign(in.static_events.size(), std::numeric_limits<double>::quiet_NaN());
  const StaticEventIndex static_index = index_static_events(in.static_events);

  const std::uint64_t samples = sample_count(T, dt);
  const std::uint64_t K = samples == 0 ? 0 : samples - 1;
  const std::uint64_t steps = samples == 0 ? 0 : continuous ? (double(K) * dt < T ? K + 1 : K) : samples;

  ccd::StepContext ctx;
  ctx.acceleration_bound = in.acceleration_bound;
  ctx.walls = in.scene->box;
  ctx.exact = method.bound.info->knowledge == ccd::Knowledge::Exact ? &traj : nullptr;
  ctx.rigid = in.rigid;

  const auto t_start = Clock::now();
  const double cpu_start = ccd::thread_cpu_seconds();
  for (std::uint64_t k = 0; k < steps; ++k) {
    if (in.cancel && in.cancel->load(std::memory_order_relaxed)) {
      cancelled = true;
      break;
    }
    const double t0 = double(k) * dt;
    const double t1 = continuous ? std::min(double(k + 1) * dt, T) : t0;
    cursor.evaluate(t0, states);
    ctx.t0 = t0;
    ctx.t1 = t1;
    ctx.start = states;

    ccd::StepTimes times;
    pipeline.run(ctx, traj, step, &times, cursor.pieces(), in.rigid);
    c.bound_s += times.bound;
    c.broad_s += times.broad;
    c.narrow_s += times.narrow;
    if (k == 0) c.first_broad_s = times.broad;
    for (const ccd::Counter& counter : pipeline.broad_phase().counters()) {
      auto it = c.counters.find(counter.name);
      if (it == c.counters.end()) it = c.counters.emplace(std::string(counter.name), 0).first;
      it->second += counter.value;
    }
    if (step.broad_stats.rebuilt) ++c.rebuilds;
    c.candidates += step.candidates.size();
    c.bound_candidates += step.passed.size();
    c.confirmed += step.contacts.size();
    c.false_positives += step.passed.size() - step.contacts.size();
    c.static_candidates += step.static_candidates.size();
    c.static_bound_candidates += step.static_passed.size();
    c.static_confirmed += step.static_contacts.size();
    c.static_tests_saved += step.static_tests_saved;

    // Bookkeeping against the truth (not timed).
    for (const ccd::PairContact& pc : step.contacts) match_contact(in, continuous, pc.pair, pc.contact, t0, t1, c);
    for (const ccd::StaticContact& sc : step.static_contacts)
      match_static_contact(in, static_index, continuous, sc, t0, t1, c);
  }
  c.cpu_s = ccd::thread_cpu_seconds() - cpu_start;
  c.total_s = seconds_since(t_start);
  return c;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// A Bounded bound knows the state at its window's start and a bound on |acceleration|:
// a velocity change inside the window is outside its assumption (docs/bounds.md,
// "Velocity changes"). Its guarantee holds when every change falls on a step's start
// k dt (the step then starts from the new velocity), never under a scheduler (windows
// start anywhere).
bool velocity_changes_on_step_starts(const ccd::Scene& scene, double dt, bool scheduled) {
  for (const ccd::Body& b : scene.bodies)
    for (const ccd::VelocityChange& c : b.velocity_changes) {
      if (scheduled) return false;
      const double k = std::round(c.t / dt);
      if (double(k) * dt != c.t) return false;  // the runner's step starts are double(k) * dt
    }
  return true;
}

}  // namespace

std::uint64_t sample_count(double horizon, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt) || !(horizon >= 0.0)) return 0;
  const double q = std::floor(horizon / dt);
  if (!(q < 9.0e15)) return 0;  // beyond exact integers in double: refused by the experiment reader
  auto K = static_cast<std::uint64_t>(q);
  while (K > 0 && double(K) * dt > horizon) --K;
  while (double(K + 1) * dt <= horizon) ++K;
  return K + 1;
}

RunRecord run_method(const RunInput& in, const MethodSpec& method, double dt) {
  RunRecord r;
  r.method = method.name;
  r.bound = method.name.substr(0, method.name.find('/'));
  r.broad_phase = std::string(method.broad_phase.info->name);
  r.options = options_json(method);
  r.knowledge = std::string(ccd::to_string(method.bound.info->knowledge));
  r.continuous = method.continuous();
  r.conservative = method.continuous() && method.bound.info->conservative &&
                   (method.bound.info->knowledge != ccd::Knowledge::Bounded ||
                    (in.acceleration_bound >= in.scene->max_acceleration() &&
                     velocity_changes_on_step_starts(*in.scene, dt, method.scheduled())));
  r.scheduled = method.scheduled();
  r.dt = dt;
  r.hz = 1.0 / dt;

  std::vector<Counts> runs;
  for (int i = 0; i < std::max(1, in.repeats); ++i) {
    bool cancelled = false;
    runs.push_back(run_once(in, method, dt, cancelled));
    if (cancelled) {
      r.cancelled = true;
      return r;
    }
  }
  const Counts& c = runs.front();
  for (const Counts& o : runs) r.counts_stable = r.counts_stable && (o == c);

  const double T = in.scene->horizon;
  const std::uint64_t samples = sample_count(T, dt);
  const std::uint64_t K = samples == 0 ? 0 : samples - 1;
  r.steps = samples == 0 ? 0 : r.continuous ? (double(K) * dt < T ? K + 1 : K) : samples;
  if (r.scheduled) r.steps = c.steps;
  r.pair_checks = c.pair_checks;
  r.narrow_calls = c.narrow_calls;
  r.refreshes = c.refreshes;

  const auto& events = in.truth->events();
  r.events = events.size();
  double lag_sum = 0.0, pen_sum = 0.0;
  // A certified (rigid) truth widens it by its largest error.
  const double slack = std::max(1e-9 * T, in.truth_error);
  for (std::size_t e = 0; e < events.size(); ++e) {
    if (!in.errors.empty() && in.errors[e].undecided) {
      // The truth could not decide it: counted apart, never a miss.
      ++r.undecided;
      continue;
    }
    if (events[e].enter == 0.0) {
      // In progress at t = 0: counted apart, outside misses, lag and penetration.
      ++r.initial_contacts;
      continue;
    }
    if (std::isnan(c.lag[e]) && in.list_missed)
      r.missed_events.push_back({events[e].a, events[e].b, events[e].enter, events[e].exit});
    if (!std::isnan(c.lag[e])) {
      ++r.detected;
      lag_sum += c.lag[e];
      pen_sum += c.penetration[e];
      r.max_lag = std::max(r.max_lag, c.lag[e]);
      r.max_penetration = std::max(r.max_penetration, c.penetration[e]);
    } else if (!r.continuous) {
      // A discrete method must detect every event that contains a sample time well
      // inside it (more than the truth's accuracy away from both ends).
      const double first = std::ceil((events[e].enter + slack) / dt);
      if (first * dt < events[e].exit - slack && first * dt <= T) ++r.self_check_undetected;
    }
  }
  r.missed = r.events - r.initial_contacts - r.detected - r.undecided;
  r.static_events = in.static_events.size();
  for (std::size_t e = 0; e < in.static_events.size(); ++e) {
    if (!in.static_errors.empty() && in.static_errors[e].undecided)
      ++r.static_undecided;
    else if (in.static_events[e].enter == 0.0)
      ++r.static_initial_contacts;
    else if (!std::isnan(c.static_lag[e]))
      ++r.static_detected;
  }
  r.static_missed = r.static_events - r.static_initial_contacts - r.static_detected - r.static_undecided;
  std::sort(r.missed_events.begin(), r.missed_events.end(), [](const MissedEvent& x, const MissedEvent& y) {
    return x.enter != y.enter ? x.enter < y.enter : x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  if (r.detected > 0) {
    r.mean_lag = lag_sum / double(r.detected);
    r.mean_penetration = pen_sum / double(r.detected);
  }
  r.static_candidates = c.static_candidates;
  r.static_bound_candidates = c.static_bound_candidates;
  r.static_confirmed = c.static_confirmed;
  r.static_tests_saved = c.static_tests_saved;
  r.static_pair_checks = c.static_pair_checks;
  r.static_narrow_calls = c.static_narrow_calls;
  r.candidates = c.candidates;
  r.bound_candidates = c.bound_candidates;
  r.confirmed = c.confirmed;
  r.false_positives = c.false_positives;
  r.counters.assign(c.counters.begin(), c.counters.end());
  r.self_check_unexpected = c.unexpected;
  r.rebuilds = c.rebuilds;
  std::vector<double> b, br, fb, n, t, cpu;
  for (const Counts& o : runs) {
    b.push_back(o.bound_s);
    br.push_back(o.broad_s);
    fb.push_back(o.first_broad_s);
    n.push_back(o.narrow_s);
    t.push_back(o.total_s);
    cpu.push_back(o.cpu_s);
  }
  r.bound_seconds = median(b);
  r.broad_seconds = median(br);
  r.first_broad_seconds = median(fb);
  r.narrow_seconds = median(n);
  r.total_seconds = median(t);
  r.seconds_per_simulated_second = r.total_seconds / T;
  r.cpu_seconds = median(cpu);
  r.cpu_seconds_per_simulated_second = r.cpu_seconds / T;
  return r;
}

namespace {

nlohmann::json counters_json(const std::vector<std::pair<std::string, std::uint64_t>>& counters) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : counters) j[name] = value;
  return j;
}

}  // namespace

nlohmann::json to_json(const RunRecord& r, bool list_missed) {
  nlohmann::json j = {{"method", r.method},
          {"bound", r.bound},
          {"broad_phase", r.broad_phase},
          {"options", r.options},
          {"knowledge", r.knowledge},
          {"continuous", r.continuous},
          {"conservative", r.conservative},
          {"dt", r.dt},
          {"hz", r.hz},
          {"steps", r.steps},
          {"events", r.events},
          {"initial_contacts", r.initial_contacts},
          {"detected", r.detected},
          {"missed", r.missed},
          {"missed_fraction", r.events > r.initial_contacts + r.undecided
                                  ? double(r.missed) / double(r.events - r.initial_contacts - r.undecided)
                                  : 0.0},
          {"undecided", r.undecided},
          {"candidates", r.candidates},
          {"bound_candidates", r.bound_candidates},
          {"confirmed", r.confirmed},
          {"false_positives", r.false_positives},
          {"false_positives_per_step", r.steps ? double(r.false_positives) / double(r.steps) : 0.0},
          {"max_penetration", r.max_penetration},
          {"mean_penetration", r.mean_penetration},
          {"mean_lag", r.mean_lag},
          {"max_lag", r.max_lag},
          {"bound_seconds", r.bound_seconds},
          {"broad_seconds", r.broad_seconds},
          {"narrow_seconds", r.narrow_seconds},
          {"total_seconds", r.total_seconds},
          {"seconds_per_simulated_second", r.seconds_per_simulated_second},
          {"cpu_seconds", r.cpu_seconds},
          {"cpu_seconds_per_simulated_second", r.cpu_seconds_per_simulated_second},
          {"first_broad_seconds", r.first_broad_seconds},
          {"counters", counters_json(r.counters)},
          {"rebuilds", r.rebuilds},
          {"static_events", r.static_events},
          {"static_initial_contacts", r.static_initial_contacts},
          {"static_detected", r.static_detected},
          {"static_missed", r.static_missed},
          {"static_undecided", r.static_undecided},
          {"static_candidates", r.static_candidates},
          {"static_bound_candidates", r.static_bound_candidates},
          {"static_confirmed", r.static_confirmed},
          {"static_tests_saved", r.static_tests_saved},
          {"self_check",
           {{"ok", r.self_check_unexpected == 0 && r.self_check_undetected == 0 && r.counts_stable},
            {"unexpected_contacts", r.self_check_unexpected},
            {"undetected_sampled_events", r.self_check_undetected},
            {"counts_stable", r.counts_stable}}}};
  if (r.scheduled) {
    j["pair_checks"] = r.pair_checks;
    j["narrow_calls"] = r.narrow_calls;
    j["refreshes"] = r.refreshes;
    j["static_pair_checks"] = r.static_pair_checks;
    j["static_narrow_calls"] = r.static_narrow_calls;
  }
  if (list_missed) {
    nlohmann::json missed = nlohmann::json::array();
    for (const MissedEvent& m : r.missed_events)
      missed.push_back({{"a", m.a}, {"b", m.b}, {"enter", m.enter}, {"exit", m.exit}});
    j["missed_events"] = std::move(missed);
  }
  return j;
}

}  // namespace ccdlab
