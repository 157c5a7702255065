#pragma once
// Method sweeps under the sanitizers (CI's memory-error pass, several times slower than
// Release): a covering subset of the names, in which every bound, every broad phase and every
// scheduler part (with its options) appears at least once. The Release build runs every name.
#include <set>
#include <string>
#include <vector>

namespace ccdlab::test {

/// `names` ("BOUND/BROADPHASE[@SCHEDULER]") in sanitizer builds cut to a covering subset, in
/// their order; in other builds `names` as given.
inline std::vector<std::string> sanitizer_cover(const std::vector<std::string>& names) {
#ifdef CCDLAB_SANITIZED
  std::set<std::string> bounds, broad_phases, schedulers;
  std::vector<std::string> kept;
  for (const std::string& name : names) {
    const std::size_t slash = name.find('/'), at = name.find('@');
    const std::string bound = name.substr(0, slash);
    const std::string broad = slash == std::string::npos ? "" : name.substr(slash + 1, at - slash - 1);
    const std::string scheduler = at == std::string::npos ? "" : name.substr(at + 1);
    const bool new_bound = bounds.insert(bound).second;
    const bool new_broad = broad_phases.insert(broad).second;
    const bool new_scheduler = schedulers.insert(scheduler).second;
    if (new_bound || new_broad || new_scheduler) kept.push_back(name);
  }
  return kept;
#else
  return names;
#endif
}

}  // namespace ccdlab::test
