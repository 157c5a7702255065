#pragma once
// One self-collision culler: it turns check intervals of a mesh's motion (x0 -> x1, linear
// per vertex; x1 = x0 is the discrete mode, a proximity check at one state) into typed
// candidates for the narrow phase (triangle CCD with the separation). A culler may keep
// state between calls (a hierarchy refitted instead of rebuilt, a broad phase's coherent
// structure); a call with another mesh or vertex count starts afresh. Instances come from
// the registry (cloth/cull/cullers.hpp).
#include <cloth/cull/candidate.hpp>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace ccd::cloth {

/// A culler's own count for its last call; the name is fixed per culler, so a caller may
/// sum it by name over intervals.
struct CullerCounter {
  std::string_view name;
  std::uint64_t value = 0;
};

class Culler {
 public:
  virtual ~Culler() = default;
  /// Sorted, unique, non-adjacent candidates for the motion x0 -> x1 (positions in metres,
  /// one per mesh vertex) with minimum separation `separation` (m, >= 0).
  virtual std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                      double separation) = 0;
  /// The culler's counters for its last call (none by default).
  virtual std::vector<CullerCounter> counters() const { return {}; }
};

}  // namespace ccd::cloth
