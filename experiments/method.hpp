#pragma once
// A method is a bound and a broad phase, named BOUND/BROADPHASE (e.g. "aabb/sap",
// "capsule/grid", "horn:4/sap"). Both halves come from their registries
// (bounds/registry.hpp, ccd/broad_phase/registry.hpp); this file only composes them.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace ccdlab {

struct MethodSpec {
  std::string name;   ///< canonical "BOUND/BROADPHASE": ":M" always written for parameterised
                      ///< bounds, in decimal without leading zeros ("horn/grid", "horn:04/grid"
                      ///< -> "horn:4/grid"), so one method has one name
  ccd::BoundSpec bound;
  const ccd::BroadPhaseInfo* broad_phase = nullptr;
  bool continuous() const { return bound.info->knowledge != ccd::Knowledge::Instant; }
};

/// Parses "BOUND/BROADPHASE"; throws std::invalid_argument with a message that lists the
/// valid bounds or broad phases.
MethodSpec parse_method(std::string_view name);

/// Every method name with default parameters (bounds x broad phases), registry order.
std::vector<std::string> all_method_names();

}  // namespace ccdlab
