#pragma once
// `mesh_sweep`: a broad phase made for the CCD of one mesh between two frames (every
// vertex moving linearly from x0 to x1). One sort and sweep along the axis of largest
// variance of the vertices' box centres (ccd/broad_phase/variance_axis.hpp): vertex boxes
// against face boxes (a bipartite sweep: the vertex-face candidates) and edge boxes
// against edge boxes (the edge-edge candidates). There are no vertex-vertex,
// face-face or vertex-edge box tests, no quadratic step, and nothing is allocated per pair.
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
// Work is cut in chunks of the sorted orders; each chunk's candidates come out in blocks
// of a buffer the caller owns (streamed: never all held), each candidate in exactly one
// chunk. The chunks do not depend on the thread count.
#include <cloth/cull/candidate.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace ccd::cloth {

struct MeshSweepOptions {
  double separation = 0.0;  ///< minimum separation, m, >= 0, finite
  bool time_halves = true;  ///< also test the boxes over [0, 1/2] and [1/2, 1]
  unsigned threads = 1;     ///< threads building and sorting the boxes (>= 1)
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
  /// The candidates of chunk k (< chunks()), passed to `sink` in blocks of at most
  /// buffer.size() (>= 1): each full block, then the rest. Safe to call concurrently.
  void sweep(std::size_t chunk, std::span<Candidate> buffer, const Sink& sink) const;
  /// Every candidate, sorted (held: for tests and the Culler interface).
  std::vector<Candidate> all(unsigned threads) const;
  /// The same rule as sweep(), pair by pair (quadratic: the tests' reference).
  std::vector<Candidate> brute_force() const;
  /// The sweep axis (0, 1, 2).
  int axis() const { return axis_; }

  /// One primitive in sweep order: its box (sweep axis, then the two others), its index
  /// and vertices (an edge's third is unused; a vertex's are unused).
  struct Item {
    double lo, hi, lo1, hi1, lo2, hi2;
    std::uint32_t id;
    std::array<std::uint32_t, 3> v;
  };
  /// The two half-interval boxes of an item, in the same axis order.
  struct Halves {
    double lo[2][3], hi[2][3];
  };

 private:
  void sweep_faces(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const;
  void sweep_vertices(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const;
  void sweep_edges(std::size_t begin, std::size_t end, std::span<Candidate> buffer, const Sink& sink) const;
  bool halves_overlap(const Halves& a, const Halves& b) const;

  int axis_ = 0;
  bool time_halves_ = true;
  std::vector<Item> vertices_, faces_, edges_;  // sorted by (lo, id)
  std::vector<Halves> vertex_halves_, face_halves_, edge_halves_;  // in the same orders
  std::size_t face_chunks_ = 0, vertex_chunks_ = 0, edge_chunks_ = 0;
};

}  // namespace ccd::cloth
