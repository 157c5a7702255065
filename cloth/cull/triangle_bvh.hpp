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
// holds the normal over the whole interval. A node's cone holds its children's.
//
// With cones, a node whose cone has a half-angle below pi/2 is not tested against itself
// only when its patch is also proved free of self-proximity over the interval: no two
// non-adjacent primitives of the patch come within the separation d (a flatness
// certificate; the proof is in docs/cloth.md#normal-cones). It needs the mesh's chart
// (ClothMesh::chart): with u_v a vertex's chart coordinates and g the smallest altitude of
// the chart's triangles, P the projection onto the plane normal to the cone's axis and
// (B, c) an affine fit of P x over the patch, if every vertex of the patch has
// |P x_v - B u_v - c| <= delta at both ends of the interval and sigma_min(B) g - 2 delta > d,
// then non-adjacent primitives of the patch stay more than d apart over the whole
// interval. Without a chart no node is skipped. So `bvh_cones` is conservative: it returns
// the pairs of `bvh` minus pairs proved to stay more than d apart.
#include <cloth/cull/candidate.hpp>
#include <ccd/geometry/aabb.hpp>

#include <Eigen/Core>

#include <span>
#include <vector>

namespace ccd::cloth {

struct BvhStats {
  std::size_t node_pairs = 0;    ///< box pairs tested
  std::size_t leaf_pairs = 0;    ///< overlapping triangle pairs
  std::size_t cone_culled = 0;   ///< nodes not tested against themselves (narrow cone and certified)
  std::size_t cone_rejected = 0; ///< nodes with a narrow cone whose certificate failed
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
  // Per node, for the flatness certificate: its triangles order_[begin, end) and the moments
  // of (chart u, mid-interval position x) over their corners (affine fit).
  struct Patch {
    std::uint32_t begin = 0, end = 0;
    double count = 0;
    Eigen::Vector2d su = Eigen::Vector2d::Zero();
    Eigen::Matrix2d suu = Eigen::Matrix2d::Zero();
    Vec3 sx = Vec3::Zero();
    Eigen::Matrix<double, 3, 2> sxu = Eigen::Matrix<double, 3, 2>::Zero();
  };
  /// The flatness certificate of node n (see the header comment) for the last refit.
  bool proved_apart(int n) const;
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
  std::vector<Patch> patches_;
  std::vector<std::uint32_t> order_;  // triangles in leaf order
  int root_ = -1;
  double chart_gap_ = 0;              // lower bound of the chart's smallest altitude; 0: no chart
  double separation_ = 0;             // of the last refit
  std::vector<Vec3> x0_, x1_;         // the last refit's states
};

}  // namespace ccd::cloth
