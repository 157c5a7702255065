#pragma once
// The one table of broad phases. The CLI (`ccdlab methods`), the tests (every entry is
// compared with `brute`) and the benchmarks all read it: a new method is one entry here.
//
// Each entry declares its options as a parameter table (ccd/util/parameters.hpp) with
// units and defaults; a spec names an entry and sets some of them:
//   NAME                    every option at its default, e.g. "grid"
//   NAME:opt=value[,...]    e.g. "grid:cell=2.0", "sap:swaps_per_endpoint=4"
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/util/parameters.hpp>

#include <memory>
#include <span>
#include <string_view>

namespace ccd {

struct BroadPhaseInfo {
  std::string_view name;         ///< e.g. "sap"
  std::string_view description;  ///< one line
  std::span<const ParameterSpec> parameters;  ///< the options (may be empty)
  std::unique_ptr<BroadPhase> (*factory)(const ParameterSet& options);

  /// An instance with the given options (checked against `parameters`).
  std::unique_ptr<BroadPhase> make(const ParameterSet& options) const { return factory(options); }
  /// An instance with every option at its default.
  std::unique_ptr<BroadPhase> make() const;
};

std::span<const BroadPhaseInfo> broad_phase_registry();

/// The entry named `name`; throws std::invalid_argument listing the valid names.
const BroadPhaseInfo& find_broad_phase(std::string_view name);

/// A broad-phase spec resolved against the registry: "grid:cell=2" -> {&grid, {cell: 2}}.
struct BroadPhaseSpec {
  const BroadPhaseInfo* info = nullptr;
  ParameterSet options;  ///< every option of the entry, defaults filled in
  std::unique_ptr<BroadPhase> make() const { return info->make(options); }
};

/// Parses "NAME" or "NAME:opt=value,..."; throws std::invalid_argument naming the bad
/// part (unknown name or option, value out of range) and listing the valid ones.
BroadPhaseSpec parse_broad_phase(std::string_view spec);

}  // namespace ccd
