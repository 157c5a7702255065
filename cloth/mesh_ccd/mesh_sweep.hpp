#pragma once
// `mesh_sweep`: a broad phase made for the CCD of one mesh between two frames (every
// vertex moving linearly from x0 to x1). A sort and sweep along one axis, cut into a grid of
// cells across it (slabs along the two other axes): vertex boxes against face boxes (a
// bipartite sweep: the vertex-face candidates) and edge boxes against edge boxes (the
// edge-edge candidates). There are no vertex-vertex, face-face or vertex-edge box tests, no
// quadratic step, and nothing is allocated per pair.
//
// Cells. A one-level sweep of a sheet is O(n^1.5): along the sweep axis a box's interval
// overlaps the starts of a whole column of the sheet; and where the boxes are long (fast
// motion), slabs along one axis alone leave whole rows of boxes apart on the third axis in
// one slab. So the slab axis and the third axis are each cut into slabs of equal width
// (cloth/mesh_ccd/sweep_layout.hpp: at most 2^16 cells and one per vertex); the sweep axis,
// the slab axis and both widths (one slab on an axis included) are chosen by the estimated
// cost of the edge-edge sweep on a sample of edges; only the speed depends on them. A box
// goes into every cell its two intervals across the sweep axis overlap. Two boxes that
// overlap share the cell of their larger first slabs on both axes, and the pair is met in
// that cell only: in each cell a box is of one of four classes, by whether the cell is in
// its first slab on the slab axis (bit 0) and on the third axis (bit 1), and a box is swept
// only against the boxes of the cell whose class completes its own (class | class' == 3).
// So each pair is tested once, whatever the layout (one cell, boxes on slab boundaries, any
// widths), and a pair sharing many cells costs no more than one sharing one.
//
// Boxes. A vertex's box holds its path over [0, 1] widened by half the separation, rounded
// outwards (cloth/cull/primitive_boxes.hpp); a face's or an edge's is the union of its
// vertices'. With `time_halves` each primitive also has the two boxes of its motion over
// [0, 1/2] and [1/2, 1] (the midpoint 0.5 x0 + 0.5 x1 widened by two steps of the doubles,
// which holds the exact midpoint), and a pair whose whole boxes overlap is kept only when
// its boxes over the same half overlap too. Primitives within the separation at a time t
// are within it in the half holding t, so that filter drops no contact. Adjacent pairs (a
// vertex of the face, edges sharing a vertex) are never candidates.
//
// Guarantee: conservative. Without `time_halves` the candidates are exactly the
// non-adjacent pairs whose whole boxes overlap (those of `boxes:brute`); with it, those
// whose boxes also overlap over one half (brute_force() is the same rule pair by pair).
//
// Work is cut in chunks of the cells' concatenated lists; each chunk's candidates come out
// in blocks of a buffer the caller owns (streamed: never all held), each candidate in
// exactly one chunk. The chunks and cells do not depend on the thread count.
#include <cloth/cull/candidate.hpp>
#include <cloth/mesh_ccd/default_init.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace ccd::cloth {

struct MeshSweepOptions {
  double separation = 0.0;  ///< minimum separation, m, >= 0, finite
  bool time_halves = true;  ///< also test the boxes over [0, 1/2] and [1/2, 1]
  unsigned threads = 1;     ///< threads building and sorting the boxes (>= 1)
  /// Slab width: 0 chooses the layout (axes and widths) by a sampled cost estimate;
  /// anything else forces it: the axes of largest and second-largest variance of the vertex
  /// boxes' centres (the sweep axis and the slab axis), slabs of this width along the slab
  /// axis when it is > 0 and finite (one slab otherwise, e.g. infinity) ...
  double slab_width = 0.0;
  /// ... and, with a forced layout, slabs of this width along the third axis when it is > 0
  /// and finite (one slab otherwise): a grid of cells. Ignored when slab_width is 0.
  double slab_width2 = 0.0;
};

class MeshSweep {
 public:
  /// Sorted items per chunk.
  static constexpr std::size_t kChunk = 1024;
  using Sink = std::function<void(std::span<const Candidate>)>;

  /// Builds the boxes and sorts them. x0 and x1 hold one finite position per vertex of
  /// `mesh` (positions at t = 0 and t = 1); `mesh` must outlive the sweep.
  void prepare(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
               const MeshSweepOptions& options);
  /// Chunks of work of the prepared sweep.
  std::size_t chunks() const { return face_chunks_ + vertex_chunks_ + edge_chunks_; }
  /// The slab axis (!= axis()) and the number of slabs along it (>= 1); the number of slabs
  /// along the third axis (>= 1); the cells (their product).
  int slab_axis() const { return slab_axis_; }
  std::size_t slabs() const { return slabs_; }
  std::size_t slabs2() const { return slabs2_; }
  std::size_t cells() const { return slabs_ * slabs2_; }
  /// Boxes placed in cells (vertices, faces and edges), counting each box once per cell.
  std::size_t slab_entries() const { return slab_vertices_.size() + slab_faces_.size() + slab_edges_.size(); }
  /// The candidates of chunk k (< chunks()), passed to `sink` in blocks of at most
  /// buffer.size() (>= 1): each full block, then the rest. Safe to call concurrently.
  void sweep(std::size_t chunk, std::span<Candidate> buffer, const Sink& sink) const;
  /// Every candidate, sorted (held: for tests and the Culler interface).
  std::vector<Candidate> all(unsigned threads) const;
  /// The same rule as sweep(), pair by pair (quadratic: the tests' reference).
  std::vector<Candidate> brute_force() const;
  /// The sweep axis (0, 1, 2).
  int axis() const { return axis_; }

  /// One primitive in sweep order: its box (sweep axis, slab axis, the third axis), its
  /// index and vertices (an edge's third is unused; a vertex's are unused).
  struct Item {
    double lo, hi, lo1, hi1, lo2, hi2;
    std::uint32_t id;
    std::array<std::uint32_t, 3> v;
  };
  /// An item in one cell: the item and its position in the sorted order (its half-interval
  /// boxes).
  struct SlabItem {
    double lo, hi, lo1, hi1, lo2, hi2;
    std::uint32_t id;
    std::uint32_t pos;
    std::array<std::uint32_t, 3> v;
  };
  /// The two half-interval boxes of an item, in the same axis order: half[0] over [0, 1/2],
  /// half[1] over [1/2, 1].
  struct Halves {
    struct Box {
      double lo[3], hi[3];
    } half[2];
  };

 private:
  void sweep_faces(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const;
  void sweep_vertices(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const;
  void sweep_edges(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const;

  int axis_ = 0, slab_axis_ = 1;
  std::size_t slabs_ = 1, slabs2_ = 1;
  // Per set: the cells' lists of items, concatenated (list cell * 4 + class at
  // [offsets[list], offsets[list + 1]), cell = slab * slabs2 + slab on the third axis).
  DefaultInitVector<SlabItem> slab_vertices_, slab_faces_, slab_edges_;
  std::vector<std::size_t> vertex_offsets_, face_offsets_, edge_offsets_;
  bool time_halves_ = true;
  DefaultInitVector<Item> vertices_, faces_, edges_;  // sorted by (lo, id)
  DefaultInitVector<Halves> vertex_halves_, face_halves_, edge_halves_;  // in the same orders
  std::size_t face_chunks_ = 0, vertex_chunks_ = 0, edge_chunks_ = 0;
};

}  // namespace ccd::cloth
