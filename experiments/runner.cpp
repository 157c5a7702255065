#include "runner.hpp"

#include <ccd/truth/contact_function.hpp>
#include <ccd/truth/pair_contact.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

namespace ccdlab {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

const char* knowledge_name(ccd::Knowledge k) {
  switch (k) {
    case ccd::Knowledge::Instant: return "instant";
    case ccd::Knowledge::Exact: return "exact";
    case ccd::Knowledge::Bounded: return "bounded";
  }
  return "unknown";
}

// Evaluates every body's state at monotonically increasing times with one cursor per
// body into its pieces (no binary search per step).
class StateCursor {
 public:
  explicit StateCursor(const ccd::Trajectories& t) : traj_(t), cursor_(t.size(), 0) {}
  void evaluate(double t, std::vector<ccd::BodyState>& out) {
    out.resize(traj_.size());
    for (std::size_t i = 0; i < traj_.size(); ++i) {
      const auto ps = traj_.pieces(i);
      std::size_t& c = cursor_[i];
      while (c + 1 < ps.size() && t >= ps[c].t1) ++c;
      out[i] = {ps[c].position(t), ps[c].velocity(t), traj_.radius(i)};
    }
  }
  /// Index of the piece of `body` used at the last evaluated time.
  std::size_t piece(std::size_t body) const { return cursor_[body]; }

 private:
  const ccd::Trajectories& traj_;
  std::vector<std::size_t> cursor_;
};

struct Counts {
  std::uint64_t candidates = 0, bound_candidates = 0, confirmed = 0, false_positives = 0, swaps = 0;
  std::uint64_t rebuilds = 0;  // steps at which the broad phase built its structure from scratch
  std::uint64_t unexpected = 0;
  double bound_s = 0, broad_s = 0, narrow_s = 0, total_s = 0;
  double first_broad_s = 0;  // the broad phase at the first step (sap: the initial sort)
  std::vector<double> lag, penetration;  // per event; NaN = not detected
  bool operator==(const Counts& o) const {
    auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
      if (x.size() != y.size()) return false;
      for (std::size_t i = 0; i < x.size(); ++i)
        if (std::isnan(x[i]) != std::isnan(y[i])) return false;
      return true;
    };
    return candidates == o.candidates && bound_candidates == o.bound_candidates && confirmed == o.confirmed &&
           false_positives == o.false_positives && unexpected == o.unexpected && swaps == o.swaps &&
           rebuilds == o.rebuilds && same(lag, o.lag);
  }
};

Counts run_once(const RunInput& in, const MethodSpec& method, double dt, bool& cancelled) {
  const ccd::Trajectories& traj = *in.trajectories;
  const TruthIndex& truth = *in.truth;
  const double T = in.scene->horizon;
  const bool continuous = method.continuous();
  // Times are matched with this slack: the truth is accurate to 1e-9 relative to T.
  const double slack = 1e-9 * T;

  auto bound = method.bound.make();
  auto broad = method.broad_phase->make();
  std::vector<ccd::BodyState> states;
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs, passed;
  struct Confirmed {
    ccd::BodyPair pair;
    double when;  // sample time, or first contact time in the step
  };
  std::vector<Confirmed> confirmed;
  StateCursor cursor(traj);

  Counts c;
  const std::size_t n_events = truth.events().size();
  c.lag.assign(n_events, std::numeric_limits<double>::quiet_NaN());
  c.penetration.assign(n_events, std::numeric_limits<double>::quiet_NaN());

  const std::uint64_t samples = sample_count(T, dt);
  const std::uint64_t K = samples == 0 ? 0 : samples - 1;
  const std::uint64_t steps = samples == 0 ? 0 : continuous ? (double(K) * dt < T ? K + 1 : K) : samples;

  ccd::StepContext ctx;
  ctx.acceleration_bound = in.acceleration_bound;
  ctx.walls = in.scene->box;
  ctx.exact = method.bound.info->knowledge == ccd::Knowledge::Exact ? &traj : nullptr;

  const auto t_start = Clock::now();
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

    auto t = Clock::now();
    bound->prepare(ctx, boxes);
    c.bound_s += seconds_since(t);

    t = Clock::now();
    broad->find_pairs(boxes, pairs);
    const double broad_step_s = seconds_since(t);
    c.broad_s += broad_step_s;
    if (k == 0) c.first_broad_s = broad_step_s;
    c.swaps += broad->stats().swaps;
    if (broad->stats().rebuilt) ++c.rebuilds;
    c.candidates += pairs.size();

    // The bound's own test over all broad-phase pairs, then the exact narrow phase over
    // the survivors: two passes, so that each is timed once per step, not per pair.
    t = Clock::now();
    passed.clear();
    for (const ccd::BodyPair& p : pairs) {
      double earliest = t0;
      if (bound->test(p.a, p.b, &earliest)) passed.push_back(p);
    }
    c.bound_s += seconds_since(t);
    c.bound_candidates += passed.size();

    t = Clock::now();
    confirmed.clear();
    for (const ccd::BodyPair& p : passed) {
      if (continuous) {
        const auto toi = ccd::pair_first_contact(traj, p.a, p.b, t0, t1);
        if (toi) confirmed.push_back({p, *toi});
      } else if (ccd::in_contact(traj, p.a, cursor.piece(p.a), p.b, cursor.piece(p.b), t0)) {
        // The truth's own definition of touching (ccd/truth/contact_function.hpp).
        confirmed.push_back({p, t0});
      }
    }
    c.narrow_s += seconds_since(t);
    c.confirmed += confirmed.size();
    c.false_positives += passed.size() - confirmed.size();

    // Bookkeeping against the truth (not timed).
    for (const Confirmed& cf : confirmed) {
      const ccd::BodyPair p = cf.pair;
      const double when = cf.when;
      const double R = states[p.a].radius + states[p.b].radius;
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
          // at the step's start from an earlier event) is detected at its own start.
          const double at = continuous ? std::max(when, ev.enter) : when;
          const ccd::Vec3 d = continuous ? ccd::Vec3(traj.position(p.a, at) - traj.position(p.b, at))
                                         : ccd::Vec3(states[p.a].position - states[p.b].position);
          c.lag[e] = std::max(0.0, at - ev.enter);
          c.penetration[e] = std::max(0.0, R - d.norm());
        }
      }
      if (!matched) ++c.unexpected;
    }
  }
  c.total_s = seconds_since(t_start);
  return c;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
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
  r.broad_phase = std::string(method.broad_phase->name);
  r.knowledge = knowledge_name(method.bound.info->knowledge);
  r.continuous = method.continuous();
  r.conservative = method.bound.info->conservative;
  r.dt = dt;

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

  const auto& events = in.truth->events();
  r.events = events.size();
  double lag_sum = 0.0, pen_sum = 0.0;
  const double slack = 1e-9 * T;
  for (std::size_t e = 0; e < events.size(); ++e) {
    if (events[e].enter == 0.0) {
      // In progress at t = 0: counted apart, outside misses, lag and penetration.
      ++r.initial_contacts;
      continue;
    }
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
  r.missed = r.events - r.initial_contacts - r.detected;
  if (r.detected > 0) {
    r.mean_lag = lag_sum / double(r.detected);
    r.mean_penetration = pen_sum / double(r.detected);
  }
  r.candidates = c.candidates;
  r.bound_candidates = c.bound_candidates;
  r.confirmed = c.confirmed;
  r.false_positives = c.false_positives;
  r.sap_swaps = c.swaps;
  r.self_check_unexpected = c.unexpected;
  r.rebuilds = c.rebuilds;
  std::vector<double> b, br, fb, n, t;
  for (const Counts& o : runs) {
    b.push_back(o.bound_s);
    br.push_back(o.broad_s);
    fb.push_back(o.first_broad_s);
    n.push_back(o.narrow_s);
    t.push_back(o.total_s);
  }
  r.bound_seconds = median(b);
  r.broad_seconds = median(br);
  r.first_broad_seconds = median(fb);
  r.narrow_seconds = median(n);
  r.total_seconds = median(t);
  r.seconds_per_simulated_second = r.total_seconds / T;
  return r;
}

nlohmann::json to_json(const RunRecord& r) {
  return {{"method", r.method},
          {"bound", r.bound},
          {"broad_phase", r.broad_phase},
          {"knowledge", r.knowledge},
          {"continuous", r.continuous},
          {"conservative", r.conservative},
          {"dt", r.dt},
          {"steps", r.steps},
          {"events", r.events},
          {"initial_contacts", r.initial_contacts},
          {"detected", r.detected},
          {"missed", r.missed},
          {"missed_fraction", r.events > r.initial_contacts ? double(r.missed) / double(r.events - r.initial_contacts) : 0.0},
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
          {"first_broad_seconds", r.first_broad_seconds},
          {"sap_swaps", r.sap_swaps},
          {"rebuilds", r.rebuilds},
          {"self_check",
           {{"ok", r.self_check_unexpected == 0 && r.self_check_undetected == 0 && r.counts_stable},
            {"unexpected_contacts", r.self_check_unexpected},
            {"undetected_sampled_events", r.self_check_undetected},
            {"counts_stable", r.counts_stable}}}};
}

}  // namespace ccdlab
