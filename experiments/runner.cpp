#include "runner.hpp"

#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <pipeline/scheduler.hpp>
#include <ccd/util/thread_cpu_time.hpp>

#include <algorithm>
#include <array>
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

// One kind of pair in one run: the stages' counts, the contacts confirmed and per truth
// event its lag (NaN = not detected).
struct PairTally {
  ccd::PairCounts stages;
  std::uint64_t confirmed = 0;
  std::vector<double> lag;
  bool operator==(const PairTally& o) const {
    if (!(stages == o.stages) || confirmed != o.confirmed || lag.size() != o.lag.size()) return false;
    for (std::size_t i = 0; i < lag.size(); ++i)
      if (std::isnan(lag[i]) != std::isnan(o.lag[i])) return false;
    return true;
  }
};

struct Counts {
  PairTally bodies, scenery;
  std::uint64_t false_positives = 0;
  std::map<std::string, std::uint64_t, std::less<>> counters;  // the broad phase's own, summed over steps
  std::uint64_t rebuilds = 0;  // steps at which the broad phase built its structure from scratch
  std::uint64_t unexpected = 0;
  std::uint64_t refreshes = 0, steps = 0;  // scheduled methods
  double bound_s = 0, broad_s = 0, narrow_s = 0, total_s = 0;
  double cpu_s = 0;  // the calling thread's CPU time over the same span as total_s
  double first_broad_s = 0;  // the broad phase at the first step (sap: the initial sort)
  std::vector<double> penetration;  // per body-body event; NaN = not detected
  bool operator==(const Counts& o) const {
    return bodies == o.bodies && scenery == o.scenery && false_positives == o.false_positives &&
           unexpected == o.unexpected && counters == o.counters && rebuilds == o.rebuilds &&
           refreshes == o.refreshes && steps == o.steps;
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
    if (std::isnan(c.bodies.lag[e])) {
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
      c.bodies.lag[e] = std::max(0.0, at - ev.enter);
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
      if (std::isnan(c.scenery.lag[e])) {
        const double at = continuous ? std::max(sc.contact.toi, ev.enter) : sc.contact.toi;
        c.scenery.lag[e] = std::max(0.0, at - ev.enter);
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
    c_.bodies.confirmed += contacts.size();
    c_.scenery.confirmed += static_contacts.size();
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
  c.bodies.lag.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.penetration.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.scenery.lag.assign(in.static_events.size(), std::numeric_limits<double>::quiet_NaN());
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
  c.bodies.stages = st.bodies;
  c.scenery.stages = st.scenery;
  c.false_positives = st.bodies.narrow_calls - c.bodies.confirmed;
  c.counters = st.counters;
  c.rebuilds = st.rebuilds;
  c.refreshes = st.refreshes;
  c.steps = st.batches;
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
  r.refreshes = c.refreshes;
  for (auto [rec, tally] : {std::pair{&r.bodies, &c.bodies}, std::pair{&r.scenery, &c.scenery}}) {
    static_cast<ccd::PairCounts&>(*rec) = tally->stages;
    rec->confirmed = tally->confirmed;
  }

  const auto& events = in.truth->events();
  PairRecord& bodies = r.bodies;
  bodies.events = events.size();
  double lag_sum = 0.0, pen_sum = 0.0;
  // A certified (rigid) truth widens it by its largest error.
  const double slack = std::max(1e-9 * T, in.truth_error);
  for (std::size_t e = 0; e < events.size(); ++e) {
    if (!in.errors.empty() && in.errors[e].undecided) {
      // The truth could not decide it: counted apart, never a miss.
      ++bodies.undecided;
      continue;
    }
    if (events[e].enter == 0.0) {
      // In progress at t = 0: counted apart, outside misses, lag and penetration.
      ++bodies.initial_contacts;
      continue;
    }
    const double lag = c.bodies.lag[e];
    if (std::isnan(lag) && in.list_missed)
      bodies.missed_events.push_back({events[e].a, events[e].b, events[e].enter, events[e].exit});
    if (!std::isnan(lag)) {
      ++bodies.detected;
      lag_sum += lag;
      pen_sum += c.penetration[e];
      r.max_lag = std::max(r.max_lag, lag);
      r.max_penetration = std::max(r.max_penetration, c.penetration[e]);
    } else if (!r.continuous) {
      // A discrete method must detect every event that contains a sample time well
      // inside it (more than the truth's accuracy away from both ends).
      const double first = std::ceil((events[e].enter + slack) / dt);
      if (first * dt < events[e].exit - slack && first * dt <= T) ++r.self_check_undetected;
    }
  }
  PairRecord& scenery = r.scenery;
  scenery.events = in.static_events.size();
  for (std::size_t e = 0; e < in.static_events.size(); ++e) {
    if (!in.static_errors.empty() && in.static_errors[e].undecided)
      ++scenery.undecided;
    else if (in.static_events[e].enter == 0.0)
      ++scenery.initial_contacts;
    else if (!std::isnan(c.scenery.lag[e]))
      ++scenery.detected;
    else if (in.list_missed)
      scenery.missed_events.push_back({in.static_events[e].body, in.static_events[e].polygon,
                                       in.static_events[e].enter, in.static_events[e].exit});
  }
  for (PairRecord* p : {&bodies, &scenery}) p->missed = p->events - p->initial_contacts - p->detected - p->undecided;
  std::sort(bodies.missed_events.begin(), bodies.missed_events.end(), [](const MissedEvent& x, const MissedEvent& y) {
    return x.enter != y.enter ? x.enter < y.enter : x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  if (bodies.detected > 0) {
    r.mean_lag = lag_sum / double(bodies.detected);
    r.mean_penetration = pen_sum / double(bodies.detected);
  }
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

// One kind of pair as the results file names it.
struct PairTwin {
  const char* prefix;     // of every field
  const char* a;          // a missed event's two indices
  const char* b;
  bool kinematic;         // writes tests_saved (the kinematic principle orders the static pairs only)
  const PairRecord& record;
};

std::array<PairTwin, 2> pair_twins(const RunRecord& r) {
  return {PairTwin{"", "a", "b", false, r.bodies}, PairTwin{"static_", "body", "polygon", true, r.scenery}};
}

}  // namespace

nlohmann::json to_json(const RunRecord& r, bool list_missed) {
  const PairRecord& bodies = r.bodies;
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
          {"missed_fraction", bodies.events > bodies.initial_contacts + bodies.undecided
                                  ? double(bodies.missed) /
                                        double(bodies.events - bodies.initial_contacts - bodies.undecided)
                                  : 0.0},
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
          {"self_check",
           {{"ok", r.self_check_unexpected == 0 && r.self_check_undetected == 0 && r.counts_stable},
            {"unexpected_contacts", r.self_check_unexpected},
            {"undetected_sampled_events", r.self_check_undetected},
            {"counts_stable", r.counts_stable}}}};
  if (r.scheduled) j["refreshes"] = r.refreshes;
  // The two kinds of pairs, by the same names: the body pairs' bare, the scenery's with
  // "static_" (a missed scenery event names its body and polygon).
  for (const PairTwin& twin : pair_twins(r)) {
    const PairRecord& p = twin.record;
    auto key = [&](const char* name) { return std::string(twin.prefix) + name; };
    j[key("events")] = p.events;
    j[key("initial_contacts")] = p.initial_contacts;
    j[key("detected")] = p.detected;
    j[key("missed")] = p.missed;
    j[key("undecided")] = p.undecided;
    j[key("candidates")] = p.candidates;
    j[key("bound_candidates")] = p.passed;
    j[key("confirmed")] = p.confirmed;
    if (twin.kinematic) j[key("tests_saved")] = p.tests_saved;
    if (r.scheduled) {
      j[key("pair_checks")] = p.checks;
      j[key("narrow_calls")] = p.narrow_calls;
    }
    if (list_missed) {
      nlohmann::json missed = nlohmann::json::array();
      for (const MissedEvent& m : p.missed_events)
        missed.push_back({{twin.a, m.a}, {twin.b, m.b}, {"enter", m.enter}, {"exit", m.exit}});
      j[key("missed_events")] = std::move(missed);
    }
  }
  return j;
}

}  // namespace ccdlab
