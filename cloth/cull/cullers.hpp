#pragma once
// The one registry of cloth self-collision cullers. A culler turns one check interval of
// a mesh's motion (x0 -> x1, linear per vertex; x1 = x0 is the discrete mode, a proximity
// check at one state) into typed candidates for the narrow phase (triangle CCD with the
// separation). `brute` is the reference: every non-adjacent pair.
//
//   brute      every pair (never drops one)
//   bvh        swept-box BVH over the triangles, built and refitted per call
//   bvh_cones  bvh with normal-cone culling of self-tests (may drop pairs: see triangle_bvh.hpp)
#include <cloth/cull/candidate.hpp>

#include <span>
#include <string_view>
#include <vector>

namespace ccd::cloth {

struct CullerEntry {
  std::string_view name;
  bool may_drop;  ///< true when the method is not proved conservative
  std::vector<Candidate> (*cull)(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                 double separation);
};

std::span<const CullerEntry> cullers();
/// nullptr when unknown.
const CullerEntry* find_culler(std::string_view name);

}  // namespace ccd::cloth
