#include "cullers.hpp"

#include <cloth/cull/triangle_bvh.hpp>

namespace ccd::cloth {

namespace {

std::vector<Candidate> brute(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3>, double) {
  return brute_force_candidates(mesh, x0.size());
}

template <bool Cones>
std::vector<Candidate> bvh(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1, double separation) {
  TriangleBvh tree(mesh, x0);
  tree.refit(x0, x1, separation / 2);
  return tree.self_candidates(Cones);
}

}  // namespace

std::span<const CullerEntry> cullers() {
  static const CullerEntry table[] = {
      {"brute", false, brute},
      {"bvh", false, bvh<false>},
      {"bvh_cones", true, bvh<true>},
  };
  return table;
}

const CullerEntry* find_culler(std::string_view name) {
  for (const CullerEntry& c : cullers())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace ccd::cloth
