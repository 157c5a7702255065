#include <pipeline/scheduler_registry.hpp>

#include <pipeline/earliest_scheduler.hpp>
#include <pipeline/fixed_step_scheduler.hpp>

#include <stdexcept>
#include <string>

namespace ccd {
namespace {

const NarrowTable& table_of(const SchedulerParts& parts) { return parts.table ? *parts.table : narrow_table(); }

std::unique_ptr<Scheduler> make_fixed(const SchedulerParts& parts, const ParameterSet& p) {
  PipelineOptions options;
  options.narrow_from_earliest = p.integer("narrow_from_earliest") != 0;
  options.kinematic = p.integer("kinematic") != 0;
  return std::make_unique<FixedStepScheduler>(parts.bound->make(), parts.bound->info->knowledge,
                                              parts.broad_phase->make(), parts.dt, options, table_of(parts));
}

std::unique_ptr<Scheduler> make_earliest(const SchedulerParts& parts, const ParameterSet& p) {
  ScheduleOptions options;
  options.window = parts.dt;
  options.stale = p.number("stale");
  options.align = p.integer("align") != 0;
  options.reach = p.number("reach");
  options.refresh_bodies = p.integer("refresh_bodies") != 0;
  options.recheck = p.integer("recheck") != 0;
  options.chunk = p.number("chunk");
  return std::make_unique<EarliestScheduler>(parts.bound->make(), parts.bound->make(), parts.bound->info->knowledge,
                                             parts.broad_phase->make(), options, table_of(parts));
}

constexpr ParameterSpec kFixedParameters[] = {
    {"narrow_from_earliest", 0.0,
     "1: the narrow phase starts at the bound test's earliest possible contact instead of the step start",
     ParameterKind::Integer, {0.0, 1.0}},
    {"kinematic", 0.0,
     "1: the kinematic principle against the scenery: each body's static pairs are solved in order of their earliest "
     "possible contact, skipping those beyond its first certain contact in the step (counted as static_tests_saved)",
     ParameterKind::Integer, {0.0, 1.0}},
};
constexpr ParameterSpec kEarliestParameters[] = {
    {"stale", 0.25,
     "a due pair check whose bounds are older than stale x dt first rebuilds them at the check time "
     "(Hubbard's refinement); 1: never, the narrow phase runs at once",
     ParameterKind::Real, {0.0, 1.0, true, false}},
    {"align", 1.0,
     "1: a refreshed window ends at the next multiple of dt, so bodies expire together; 0: at its start + dt",
     ParameterKind::Integer, {0.0, 1.0}},
    {"reach", 0.0,
     "> 0: speed-adapted windows, each body's the longest dt / 2^k over which it moves at most reach x the "
     "bodies' mean radius (fast bodies refresh often, slow ones rarely); 0: every window dt",
     ParameterKind::Real, {0.0, 1e9}},
    {"refresh_bodies", 0.0,
     "0: a refinement builds the pair's own bounds; 1: it refreshes both bodies' bounds (broad-phase update, "
     "every pair of theirs re-tested)",
     ParameterKind::Integer, {0.0, 1.0}},
    {"recheck", 0.0,
     "1: a due pair is first re-checked with speed bounds from both bodies' states at the check time (no bound "
     "built; stale and refresh_bodies unused), then the narrow phase runs from that earliest time over one chunk "
     "and the pair is re-checked at its end",
     ParameterKind::Integer, {0.0, 1.0}},
    {"chunk", 2.0,
     "with recheck: a narrow call covers the time in which the pair's distance may change by chunk x the sum of "
     "their radii; 0: the rest of the common window",
     ParameterKind::Real, {0.0, 1e9}},
};

const SchedulerInfo kSchedulers[] = {
    {"fixed", "fixed steps of dt: every bound, every candidate pair, every step", kFixedParameters,
     &make_fixed},
    {"earliest",
     "per-pair checks at the earliest possible contact, per-body windows of at most dt refreshed one by one",
     kEarliestParameters, &make_earliest},
};

std::string valid_names() {
  std::string s;
  for (const SchedulerInfo& x : kSchedulers) s += (s.empty() ? "" : ", ") + std::string(x.name);
  return s;
}

std::string valid_options(const SchedulerInfo& info) {
  std::string s = "valid: ";
  for (const ParameterSpec& p : info.parameters) s += (s.size() > 7 ? ", " : "") + describe_parameter(p);
  return s;
}

}  // namespace

std::span<const SchedulerInfo> scheduler_registry() { return kSchedulers; }

bool SchedulerSpec::earliest() const { return info && info->name == "earliest"; }

std::unique_ptr<Scheduler> SchedulerSpec::make(const SchedulerParts& parts) const {
  if (!info || !parts.bound || !parts.bound->info || !parts.broad_phase || !parts.broad_phase->info)
    throw std::invalid_argument("a scheduler needs a bound and a broad phase");
  try {
    return info->factory(parts, options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("scheduler '" + std::string(info->name) + "': " + e.what());
  }
}

SchedulerSpec parse_scheduler(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::string_view name = spec.substr(0, colon);
  const SchedulerInfo* info = nullptr;
  for (const SchedulerInfo& x : kSchedulers)
    if (x.name == name) info = &x;
  if (!info)
    throw std::invalid_argument("unknown scheduler '" + std::string(name) + "'; valid schedulers: " + valid_names());
  if (colon == std::string_view::npos) return {info, resolve_parameters(info->parameters, {})};
  try {
    return {info, resolve_parameters(info->parameters,
                                     option_values_from_text(spec.substr(colon + 1), info->parameters[0].name))};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("scheduler '" + std::string(spec) + "': " + e.what() + " (" + valid_options(*info) +
                                ")");
  }
}

SchedulerSpec default_scheduler() { return parse_scheduler("fixed"); }

}  // namespace ccd
