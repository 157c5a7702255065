#pragma once
// A bounding volume hierarchy over a mesh's triangles for self-collision culling, with
// normal cones (Volino and Magnenat-Thalmann's "positive vector").
//
// The tree's topology is built once from one state (median splits of triangle centroids
// along the longest axis). Each check interval refits it: a leaf's box holds its triangle
// at both ends of the interval (so, with linear motion, all of it in between: the swept
// box), inflated by half the separation. Then a box overlap is necessary for two
// primitives to come within the separation. Passing x1 = x0 gives the discrete mode (the
// boxes of one state).
//
// Normal cones: under linear motion a triangle's normal n(t) = e1(t) x e2(t) is a
// quadratic with Bernstein coefficients n(0), (e1(0) x e2(1) + e1(1) x e2(0)) / 2 and
// n(1). Every n(t) is a non-negative combination of them, so a cone holding the three
// holds the normal over the whole interval. A node's cone holds its children's. When a
// node's cone has a half-angle below pi/2, every normal of its patch is on one side of
// the axis, and the node is not tested against itself. A patch that faces one way cannot
// fold onto itself, provided its boundary, projected along the axis, does not cross
// itself. That contour test is not done here, so `bvh_cones` may drop true contacts.
// Its tests check, on the cloth scenes, that every dropped pair is contact-free.
#include <cloth/cull/candidate.hpp>

#include <span>
#include <vector>

namespace ccd::cloth {

struct BvhStats {
  std::size_t node_pairs = 0;    ///< box pairs tested
  std::size_t leaf_pairs = 0;    ///< overlapping triangle pairs
  std::size_t cone_culled = 0;   ///< nodes not tested against themselves thanks to their cone
};

class TriangleBvh {
 public:
  TriangleBvh(const ClothMesh& mesh, std::span<const Vec3> x);
  /// Boxes and cones for the motion from x0 to x1, boxes inflated by `inflate` (>= 0).
  void refit(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate);
  /// Sorted, unique, non-adjacent candidates whose primitives' boxes overlap.
  std::vector<Candidate> self_candidates(bool use_cones, BvhStats* stats = nullptr) const;

 private:
  struct Node {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    Vec3 axis = Vec3::UnitZ();  // normal cone axis (unit)
    double half_angle = 0;  // radians; >= pi means "any direction"
    int left = -1, right = -1;
    int triangle = -1;      // leaf
  };
  int build(std::vector<std::uint32_t>& tris, std::size_t begin, std::size_t end, std::span<const Vec3> x);
  void refit_node(int n, std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate);
  void self(int n, bool cones, std::vector<Candidate>& out, BvhStats& s) const;
  void pair(int a, int b, std::vector<Candidate>& out, BvhStats& s) const;
  void emit(std::uint32_t ta, std::uint32_t tb, std::vector<Candidate>& out) const;

  const ClothMesh* mesh_;
  std::vector<std::array<std::uint32_t, 3>> triangle_edges_;
  std::vector<Node> nodes_;
  int root_ = -1;
};

}  // namespace ccd::cloth
