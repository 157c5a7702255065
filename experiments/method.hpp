#pragma once
// A method is a bound and a broad phase, named BOUND/BROADPHASE (e.g. "aabb/sap",
// "capsule/grid", "horn:4/sap", "capsule/grid:cell=2"), each half a spec with its options
// (syntax in bounds/registry.hpp and ccd/broad_phase/registry.hpp). Both halves come from their registries
// (bounds/registry.hpp, ccd/broad_phase/registry.hpp); this file only composes them.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace ccdlab {

struct MethodSpec {
  std::string name;   ///< "BOUND/BROADPHASE" as given (options kept as written)
  ccd::BoundSpec bound;
  ccd::BroadPhaseSpec broad_phase;
  bool continuous() const { return bound.info->knowledge != ccd::Knowledge::Instant; }
};

/// Parses "BOUND/BROADPHASE"; throws std::invalid_argument with a message that lists the
/// valid bounds or broad phases.
MethodSpec parse_method(std::string_view name);

/// The options the method runs with, every default filled in:
/// {"bound": {"pieces": 4}, "broad_phase": {"cell": 0, "threads": 1}}.
nlohmann::json options_json(const MethodSpec& method);

/// Every method name with default parameters (bounds x broad phases), registry order.
std::vector<std::string> all_method_names();

}  // namespace ccdlab
