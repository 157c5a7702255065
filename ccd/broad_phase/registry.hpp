#pragma once
// The one table of broad phases. The CLI (`ccdlab methods`), the tests (every entry is
// compared with `brute`) and the benchmarks all read it: a new method is one entry here.
#include <ccd/broad_phase/broad_phase.hpp>

#include <memory>
#include <span>
#include <string_view>

namespace ccd {

struct BroadPhaseInfo {
  std::string_view name;         ///< e.g. "sap"
  std::string_view description;  ///< one line
  std::unique_ptr<BroadPhase> (*make)();
};

std::span<const BroadPhaseInfo> broad_phase_registry();

/// The entry named `name`; throws std::invalid_argument listing the valid names.
const BroadPhaseInfo& find_broad_phase(std::string_view name);

}  // namespace ccd
