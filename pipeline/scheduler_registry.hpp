#pragma once
// The one table of schedulers: what drives the step pipeline over an experiment's horizon.
// A method names one after its broad phase, BOUND/BROADPHASE@SCHEDULER[:opt=value,...];
// without "@" it is `fixed`, every option at its default.
//   fixed      steps [k dt, (k+1) dt]: every body's bound over every step, every
//              candidate pair tested, the narrow phase for every pair that passes
//              (pipeline/fixed_step_scheduler.hpp, one pipeline/step_pipeline.hpp
//              run per step).
//   earliest   Hubbard's earliest-contact scheduling (pipeline/earliest_scheduler.hpp):
//              dt is the longest window a body's bound may cover; each pair is looked
//              at again only at the earliest time its bounds allow contact.
// Each entry declares its options as a parameter table (ccd/util/parameters.hpp) and has
// a factory that reads them: SchedulerSpec::make builds the scheduler (pipeline/scheduler.hpp)
// of a method from its bound, its broad phase and dt, the options as the spec gave them.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/util/parameters.hpp>

#include <memory>
#include <span>
#include <string_view>

namespace ccd {

class NarrowTable;
class Scheduler;

/// What a scheduler is built from besides its own options.
struct SchedulerParts {
  const BoundSpec* bound = nullptr;            ///< makes the bound instances it needs
  const BroadPhaseSpec* broad_phase = nullptr;
  double dt = 0.0;                      ///< the step (fixed) or the longest window (earliest), > 0
  const NarrowTable* table = nullptr;   ///< null: narrow_table()
};

/// Builds a scheduler from its parts and its resolved options; throws std::invalid_argument
/// naming the option or the part it cannot take.
using SchedulerFactory = std::unique_ptr<Scheduler> (*)(const SchedulerParts& parts, const ParameterSet& options);

struct SchedulerInfo {
  std::string_view name;         ///< "fixed", "earliest"
  std::string_view description;  ///< one line
  std::span<const ParameterSpec> parameters;
  SchedulerFactory factory;
};

std::span<const SchedulerInfo> scheduler_registry();

/// A scheduler spec resolved against the registry: "earliest:stale=0.5" -> {&earliest, {stale: 0.5}}.
struct SchedulerSpec {
  const SchedulerInfo* info = nullptr;
  ParameterSet options;  ///< every option of the entry, defaults filled in
  bool earliest() const;  ///< the `earliest` scheduler (otherwise `fixed`)
  std::unique_ptr<Scheduler> make(const SchedulerParts& parts) const;
};

/// Parses "NAME" or "NAME:opt=value,..." (a bare value sets the first option); throws
/// std::invalid_argument naming the bad part and listing the valid names or options.
SchedulerSpec parse_scheduler(std::string_view spec);

/// `fixed` with every option at its default.
SchedulerSpec default_scheduler();

}  // namespace ccd
