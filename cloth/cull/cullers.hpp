#pragma once
// The one registry of cloth self-collision cullers (the interface: cloth/cull/culler.hpp).
//
//   brute               every non-adjacent pair (the reference; never drops one)
//   bvh                 swept-box BVH over the triangles, refitted between calls (conservative)
//   bvh_cones           bvh with normal-cone culling of self-tests (may drop pairs: triangle_bvh.hpp)
//   sensors             particle sensors flag folds, the bvh tests what they flag (may drop pairs:
//                       sensor_culler.hpp)
//   mesh_sweep          sort and sweep on the axis of largest variance, vertices against faces and
//                       edges against edges, with half-interval boxes (conservative;
//                       cloth/mesh_ccd/mesh_sweep.hpp)
//   boxes:<broad phase> primitive boxes through a broad phase of ccd/broad_phase/registry.hpp,
//                       e.g. "boxes:sap", "boxes:grid:cell=0.1" (conservative)
//
// `cullers()` lists each method once, with `boxes:` over every broad phase at its default
// options; `find_culler` also accepts a `boxes:` spec with options.
#include <cloth/cull/culler.hpp>

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ccd::cloth {

struct CullerEntry {
  std::string name;
  bool may_drop;  ///< true when the method is not proved conservative
  std::string description;  ///< one line
  std::function<std::unique_ptr<Culler>()> make;  ///< a new instance (state kept between its calls)

  /// One check interval with a fresh instance (nothing kept between calls).
  std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                              double separation) const {
    return make()->cull(mesh, x0, x1, separation);
  }
};

std::span<const CullerEntry> cullers();
/// nullptr when unknown (or a `boxes:` spec the broad-phase registry refuses).
const CullerEntry* find_culler(std::string_view name);

}  // namespace ccd::cloth
