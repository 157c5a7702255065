#pragma once
// A bounding volume hierarchy over a mesh's triangles for self-collision culling, with
// normal cones (Volino and Magnenat-Thalmann's "positive vector").
//
// The tree's topology is built from one state (median splits of triangle centroids along
// the longest axis). Each check interval refits it: a leaf's box holds its triangle at both
// ends of the interval (so, with linear motion, all of it in between: the swept box),
// inflated by half the separation. Then a box overlap is necessary for two primitives to
// come within the separation. Passing x1 = x0 gives the discrete mode (the boxes of one
// state). A refitted tree stays correct however the mesh moves, only slower to traverse:
// `quality()` measures that, and a caller rebuilds when it degrades (cloth/cull/bvh_culler.hpp).
//
// Candidates: each vertex and each edge is owned by one triangle containing it. An
// overlapping pair of leaves (ta, tb) emits the vertex-face pairs of ta's vertices with tb
// (and the reverse) and the edge-edge pairs of their edges, each only when the two
// primitives' own boxes overlap too. A primitive's box lies in its owner's, so every
// non-adjacent pair with overlapping primitive boxes is emitted, exactly once, whatever the
// topology: `bvh` returns exactly the pairs whose primitive boxes overlap.
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
#include <ccd/geometry/aabb.hpp>

#include <span>
#include <vector>

namespace ccd::cloth {

struct BvhStats {
  std::size_t node_pairs = 0;    ///< box pairs tested
  std::size_t leaf_pairs = 0;    ///< overlapping triangle pairs
  std::size_t cone_culled = 0;   ///< nodes not tested against themselves thanks to their cone
};

/// Sorts candidates in their (kind, a, b) order, as std::sort would, in linear time (a
/// radix sort on packed keys; std::sort when the keys would not fit 64 bits).
void sort_candidates(std::vector<Candidate>& c);

class TriangleBvh {
 public:
  /// The topology from the state x (one position per mesh vertex).
  TriangleBvh(const ClothMesh& mesh, std::span<const Vec3> x);
  /// A new topology from the state x, for the same mesh.
  void rebuild(std::span<const Vec3> x);
  /// Boxes and cones for the motion from x0 to x1, boxes inflated by `inflate` (>= 0).
  void refit(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate);
  /// Sorted, unique, non-adjacent candidates whose primitives' boxes overlap. With
  /// `active` (one flag per vertex, non-zero = active; empty = all active), only pairs of
  /// primitives that both have an active vertex, and only the subtrees holding one.
  std::vector<Candidate> self_candidates(bool use_cones, BvhStats* stats = nullptr,
                                         std::span<const std::uint8_t> active = {}) const;
  /// After a refit: the summed surface areas of the internal nodes' boxes over the root's
  /// (the surface area heuristic's traversal cost: about the depth for a well-built tree,
  /// up to the node count when every box spans the whole mesh).
  double quality() const;
  const ClothMesh& mesh() const { return *mesh_; }
  std::size_t vertex_count() const { return vertex_owner_.size(); }

 private:
  struct alignas(64) Node {  // one cache line; an internal node's left child is the next node
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    double size = 0;        // |hi - lo|: steers which node of a pair is split
    int right = -1;
    int triangle = -1;      // leaf
  };
  struct Cone {  // per node, apart from the boxes the traversal reads most
    Vec3 axis = Vec3::UnitZ();  // normal cone axis (unit)
    double half_angle = 0;      // radians; >= pi means "any direction"
  };
  int build(std::vector<std::uint32_t>& tris, std::size_t begin, std::size_t end, std::span<const Vec3> x);
  void refit_node(int n, std::span<const Vec3> x0, std::span<const Vec3> x1);
  struct Traversal {
    bool cones;
    std::span<const std::uint8_t> active;  // per vertex (empty: all)
    std::vector<std::uint8_t> node_active;  // per node (empty: all)
    std::vector<Candidate>& out;
    BvhStats& stats;
  };
  void self(int n, Traversal& tr) const;
  void pair(int a, int b, Traversal& tr) const;
  void orphan(std::uint32_t v, int n, Traversal& tr) const;
  void emit(std::uint32_t ta, std::uint32_t tb, Traversal& tr) const;
  std::uint8_t mark_active(int n, Traversal& tr) const;

  const ClothMesh* mesh_;
  std::vector<std::array<std::uint32_t, 3>> triangle_edges_;
  std::vector<std::uint32_t> vertex_owner_, edge_owner_;  // the triangle owning each
  std::vector<std::uint32_t> orphans_;                    // vertices on no triangle
  struct Owned {  // a triangle's own vertices and edges (each listed once)
    std::uint32_t vertices[3], edges[3];
    int vertex_count = 0, edge_count = 0;
  };
  std::vector<Owned> owned_;
  std::vector<Aabb> vertex_boxes_;                        // after refit: inflated swept boxes
  std::vector<Aabb> edge_boxes_, triangle_boxes_;         // after refit: unions of vertex boxes
  mutable std::size_t last_count_ = 0;                    // candidates of the last call (reserve)
  std::vector<Node> nodes_;
  std::vector<Cone> cones_;
  int root_ = -1;
};

}  // namespace ccd::cloth
