#pragma once
// A method is a bound and a broad phase, named BOUND/BROADPHASE (e.g. "aabb/sap",
// "capsule/grid", "horn:4/sap", "capsule/grid:cell=2"), optionally driven by a scheduler
// named after "@" (BOUND/BROADPHASE@SCHEDULER, e.g. "horn:4/grid@earliest",
// "capsule/sap@earliest:stale=0.5"; none means `fixed`: pipeline/scheduler_registry.hpp),
// each part a spec with its options
// (syntax in bounds/registry.hpp and ccd/broad_phase/registry.hpp). Both halves come from their registries
// (bounds/registry.hpp, ccd/broad_phase/registry.hpp); this file only composes them.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <pipeline/scheduler_registry.hpp>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace ccdlab {

/// A method parsed once (parse_method); every consumer takes this, never the string.
struct MethodSpec {
  std::string name;   ///< "BOUND/BROADPHASE[@SCHEDULER]" as given (options kept as written)
  std::string bound_text;        ///< the BOUND part as written ("horn:4")
  std::string broad_phase_text;  ///< the BROADPHASE part as written ("grid:cell=2")
  std::string scheduler_text;    ///< the SCHEDULER part as written ("" when the name has no "@")
  ccd::BoundSpec bound;
  ccd::BroadPhaseSpec broad_phase;
  ccd::SchedulerSpec scheduler;    ///< `fixed` with its defaults when the name has no "@"
  bool scheduler_named = false;    ///< the name has an "@SCHEDULER" part
  bool continuous() const { return bound.info->knowledge != ccd::Knowledge::Instant; }
  bool scheduled() const { return scheduler.earliest(); }
  /// BOUND/BROADPHASE: the method without its scheduler (the fixed-step method).
  std::string fixed_step_name() const { return bound_text + "/" + broad_phase_text; }
  /// The name composed from its parts; parse_method(to_string()) is this method.
  std::string to_string() const { return fixed_step_name() + (scheduler_named ? "@" + scheduler_text : ""); }
  /// The same method as written the same way (the spelling decides, as in results files).
  friend bool operator==(const MethodSpec& a, const MethodSpec& b) { return a.name == b.name; }
};

/// Parses "BOUND/BROADPHASE[@SCHEDULER]"; throws std::invalid_argument with a message that
/// names the part that is wrong (the form, the bound, the broad phase or the scheduler) and
/// lists the valid names. `@earliest` needs a space-time bound.
MethodSpec parse_method(std::string_view name);

/// The methods' names, as an experiment and its results list them.
std::vector<std::string> method_names(const std::vector<MethodSpec>& methods);

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
