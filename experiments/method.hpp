#pragma once
// A method is a bound and a broad phase, named BOUND/BROADPHASE (e.g. "aabb/sap",
// "capsule/grid", "horn:4/sap", "capsule/grid:cell=2"), optionally driven by a scheduler
// named after "@" (BOUND/BROADPHASE@SCHEDULER, e.g. "horn:4/grid@earliest",
// "capsule/sap@earliest:stale=0.5"; none means `fixed`: ccd/pipeline/scheduler_registry.hpp),
// each part a spec with its options
// (syntax in bounds/registry.hpp and ccd/broad_phase/registry.hpp). Both halves come from their registries
// (bounds/registry.hpp, ccd/broad_phase/registry.hpp); this file only composes them.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/pipeline/scheduler_registry.hpp>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace ccdlab {

struct MethodSpec {
  std::string name;   ///< "BOUND/BROADPHASE" as given (options kept as written)
  ccd::BoundSpec bound;
  ccd::BroadPhaseSpec broad_phase;
  ccd::SchedulerSpec scheduler;    ///< `fixed` with its defaults when the name has no "@"
  bool scheduler_named = false;    ///< the name has an "@SCHEDULER" part
  bool continuous() const { return bound.info->knowledge != ccd::Knowledge::Instant; }
  bool scheduled() const { return scheduler.earliest(); }
};

/// Parses "BOUND/BROADPHASE[@SCHEDULER]"; throws std::invalid_argument with a message that
/// lists the valid bounds, broad phases or schedulers. `@earliest` needs a space-time bound.
MethodSpec parse_method(std::string_view name);

/// The options the method runs with, every default filled in:
/// {"bound": {"pieces": 4}, "broad_phase": {"cell": 0, "threads": 1}}, plus
/// "scheduler": {"name": "earliest", "stale": 0.25} when the name has an "@" part.
nlohmann::json options_json(const MethodSpec& method);

/// Every method name with default parameters (bounds x broad phases), registry order,
/// fixed-step only.
std::vector<std::string> all_method_names();

/// Every `@earliest` method with default parameters: each space-time bound with each
/// broad phase, registry order.
std::vector<std::string> scheduled_method_names();

}  // namespace ccdlab
