#include <pipeline/fixed_step_scheduler.hpp>

#include <ccd/motion/state_cursor.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace ccd {
namespace {

// One step's stage into the run's counts: every candidate is one check, every passed pair
// one narrow call unless the kinematic principle skipped it.
template <class Pair, class Contact>
void add_step(PairCounts& counts, const PairStage<Pair, Contact>& step) {
  counts.candidates += step.candidates.size();
  counts.checks += step.candidates.size();
  counts.passed += step.passed.size();
  counts.narrow_calls += step.passed.size() - step.tests_saved;
  counts.tests_saved += step.tests_saved;
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

std::uint64_t fixed_step_count(double horizon, double dt, bool continuous) {
  const std::uint64_t samples = sample_count(horizon, dt);
  if (samples == 0 || !continuous) return samples;
  const std::uint64_t K = samples - 1;
  return double(K) * dt < horizon ? K + 1 : K;
}

FixedStepScheduler::FixedStepScheduler(std::unique_ptr<Bound> bound, Knowledge knowledge,
                                       std::unique_ptr<BroadPhase> broad, double dt, PipelineOptions options,
                                       const NarrowTable& table)
    : pipeline_(std::move(bound), knowledge, std::move(broad), table, options), knowledge_(knowledge), dt_(dt) {
  if (!(dt > 0.0 && std::isfinite(dt))) throw std::invalid_argument("fixed steps need a finite dt > 0");
}

void FixedStepScheduler::set_scenery(std::span<const StaticPolygon> polygons) { pipeline_.set_scenery(polygons); }

bool FixedStepScheduler::run(const ScheduleInput& in, ScheduleResult& out) {
  const Trajectories& motion = in.motion->centres();
  const double T = in.horizon;
  const bool continuous = knowledge_ != Knowledge::Instant;
  out = {};
  ScheduleStats& st = out.stats;
  StateCursor cursor(motion);
  StepContext ctx;
  ctx.acceleration_bound = in.acceleration_bound;
  ctx.walls = in.walls;
  ctx.exact = knowledge_ == Knowledge::Exact ? &motion : nullptr;
  ctx.motion = in.motion;

  const std::uint64_t steps = fixed_step_count(T, dt_, continuous);
  for (std::uint64_t k = 0; k < steps; ++k) {
    if (in.cancel && in.cancel->load(std::memory_order_relaxed)) {
      out.finished = false;
      break;
    }
    const double t0 = double(k) * dt_;
    const double t1 = continuous ? std::min(double(k + 1) * dt_, T) : t0;
    cursor.evaluate(t0, states_);
    ctx.t0 = t0;
    ctx.t1 = t1;
    ctx.start = states_;

    StepTimes times;
    pipeline_.run(ctx, step_, in.timed ? &times : nullptr, cursor.pieces());
    out.times.bound += times.bound;
    out.times.broad += times.broad;
    out.times.narrow += times.narrow;
    if (k == 0) out.first_broad_seconds = times.broad;
    for (const Counter& counter : pipeline_.broad_phase().counters()) {
      auto it = st.counters.find(counter.name);
      if (it == st.counters.end()) it = st.counters.emplace(std::string(counter.name), 0).first;
      it->second += counter.value;
    }
    ++st.batches;
    st.refreshes += motion.size();
    if (step_.broad_stats.rebuilt) ++st.rebuilds;
    add_step(st.bodies, step_.bodies);
    add_step(st.scenery, step_.scenery);

    std::vector<ScheduledContact>& contacts = in.sink ? step_contacts_ : out.contacts;
    std::vector<ScheduledStaticContact>& static_contacts = in.sink ? step_static_contacts_ : out.static_contacts;
    if (in.sink) {
      contacts.clear();
      static_contacts.clear();
    }
    for (const PairContact& pc : step_.bodies.contacts) contacts.push_back({pc.pair, pc.contact, t0, t1});
    for (const StaticContact& sc : step_.scenery.contacts) static_contacts.push_back({sc.pair, sc.contact, t0, t1});
    if (in.sink && (!contacts.empty() || !static_contacts.empty())) in.sink->found(contacts, static_contacts);
  }
  return out.finished;
}

}  // namespace ccd
