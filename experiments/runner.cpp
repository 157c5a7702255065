#include "runner.hpp"

#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <pipeline/scheduler.hpp>
#include <ccd/util/thread_cpu_time.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
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
      // Shaped pairs: the narrow phase's bound at its own time (the sphere formula would
      // measure the enclosing spheres).
      const bool spheres = in.motion->kind(p.a) == ccd::ShapeKind::Sphere &&
                           in.motion->kind(p.b) == ccd::ShapeKind::Sphere;
      const double signed_distance = at == when || !spheres
                                         ? contact.signed_distance
                                         : ccd::sphere_signed_distance(in.motion->centres(), p.a, p.b, at);
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

// Matches the contacts a run hands over with the truth as they are found, and counts them.
class ContactMatcher final : public ccd::ContactSink {
 public:
  ContactMatcher(const RunInput& in, bool continuous, Counts& c)
      : in_(in), continuous_(continuous), c_(c), static_index_(index_static_events(in.static_events)) {}
  void found(std::span<const ccd::ScheduledContact> contacts,
             std::span<const ccd::ScheduledStaticContact> static_contacts) override {
    c_.confirmed += contacts.size();
    c_.static_confirmed += static_contacts.size();
    for (const ccd::ScheduledContact& sc : contacts)
      match_contact(in_, continuous_, sc.pair, sc.contact, sc.from, sc.to, c_);
    for (const ccd::ScheduledStaticContact& sc : static_contacts)
      match_static_contact(in_, static_index_, continuous_, {sc.pair, sc.contact}, sc.from, sc.to, c_);
  }

 private:
  const RunInput& in_;
  bool continuous_;
  Counts& c_;
  StaticEventIndex static_index_;
};

// One run of the method's scheduler over the horizon (fixed steps of dt, or the earliest
// scheduler with windows of at most dt: pipeline/scheduler_registry.hpp), timed, its
// contacts matched with the truth.
Counts run_once(const RunInput& in, const MethodSpec& method, double dt, bool& cancelled) {
  Counts c;
  const std::size_t n_events = in.truth->events().size();
  c.lag.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.penetration.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.static_lag.assign(in.static_events.size(), std::numeric_limits<double>::quiet_NaN());
  const std::unique_ptr<ccd::Scheduler> scheduler = method.scheduler.make({&method.bound, &method.broad_phase, dt});
  scheduler->set_scenery(in.scene->scenery);
  ContactMatcher matcher(in, method.continuous(), c);
  ccd::ScheduleInput input;
  input.motion = in.motion;
  input.horizon = in.scene->horizon;
  input.acceleration_bound = in.acceleration_bound;
  input.walls = in.scene->box;
  input.cancel = in.cancel;
  input.sink = &matcher;
  ccd::ScheduleResult result;
  const auto t_start = Clock::now();
  const double cpu_start = ccd::thread_cpu_seconds();
  cancelled = !scheduler->run(input, result);
  c.cpu_s = ccd::thread_cpu_seconds() - cpu_start;
  c.total_s = seconds_since(t_start);
  c.bound_s = result.times.bound;
  c.broad_s = result.times.broad;
  c.narrow_s = result.times.narrow;
  c.first_broad_s = result.first_broad_seconds;
  const ccd::ScheduleStats& st = result.stats;
  c.candidates = st.candidates;
  c.bound_candidates = st.passed;
  c.false_positives = st.narrow_calls - c.confirmed;
  c.counters = st.counters;
  c.rebuilds = st.rebuilds;
  c.pair_checks = st.pair_checks;
  c.narrow_calls = st.narrow_calls;
  c.refreshes = st.refreshes;
  c.steps = st.batches;
  c.static_candidates = st.static_candidates;
  c.static_bound_candidates = st.static_passed;
  c.static_tests_saved = st.static_tests_saved;
  c.static_pair_checks = st.static_checks;
  c.static_narrow_calls = st.static_narrow_calls;
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

RunRecord run_method(const RunInput& in, const MethodSpec& method, double dt) {
  RunRecord r;
  r.method = method.name;
  r.bound = method.bound_text;
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
  r.steps = c.steps;  // fixed: the steps or samples; scheduled: the refresh events
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
    else if (in.list_missed)
      r.static_missed_events.push_back({in.static_events[e].body, in.static_events[e].polygon,
                                        in.static_events[e].enter, in.static_events[e].exit});
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
    nlohmann::json missed_static = nlohmann::json::array();
    for (const MissedEvent& m : r.static_missed_events)
      missed_static.push_back({{"body", m.a}, {"polygon", m.b}, {"enter", m.enter}, {"exit", m.exit}});
    j["static_missed_events"] = std::move(missed_static);
  }
  return j;
}

}  // namespace ccdlab
