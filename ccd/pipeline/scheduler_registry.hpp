#pragma once
// The one table of schedulers: what drives the step pipeline over an experiment's horizon.
// A method names one after its broad phase, BOUND/BROADPHASE@SCHEDULER[:opt=value,...];
// without "@" it is `fixed`, every option at its default (today's loop).
//   fixed      steps [k dt, (k+1) dt]: every body's bound over every step, every
//              candidate pair tested, the narrow phase for every pair that passes
//              (ccd/pipeline/step_pipeline.hpp).
//   earliest   Hubbard's earliest-contact scheduling (ccd/pipeline/earliest_scheduler.hpp):
//              dt is the longest window a body's bound may cover; each pair is looked
//              at again only at the earliest time its bounds allow contact.
// Each entry declares its options as a parameter table (ccd/util/parameters.hpp).
#include <ccd/util/parameters.hpp>

#include <span>
#include <string_view>

namespace ccd {

struct SchedulerInfo {
  std::string_view name;         ///< "fixed", "earliest"
  std::string_view description;  ///< one line
  std::span<const ParameterSpec> parameters;
};

std::span<const SchedulerInfo> scheduler_registry();

/// A scheduler spec resolved against the registry: "earliest:stale=0.5" -> {&earliest, {stale: 0.5}}.
struct SchedulerSpec {
  const SchedulerInfo* info = nullptr;
  ParameterSet options;  ///< every option of the entry, defaults filled in
  bool earliest() const;  ///< the `earliest` scheduler (otherwise `fixed`)
};

/// Parses "NAME" or "NAME:opt=value,..." (a bare value sets the first option); throws
/// std::invalid_argument naming the bad part and listing the valid names or options.
SchedulerSpec parse_scheduler(std::string_view spec);

/// `fixed` with every option at its default.
SchedulerSpec default_scheduler();

}  // namespace ccd
