#pragma once
// `grid`: uniform grid built by sorting (cell key, body) at every frame its Verlet list
// (below) cannot serve. Exact: candidate pairs get the closed-interval box test, so it
// reports the same pairs as `brute`.
//
// Cell-size rule: s = max(largest box extent over all axes and bodies, options.cell_size)
// times (1 + 2^-20), raised if needed so that there are at most 2^20 cells per axis and
// 2^32 cells in all (then the grid only gets coarser: still exact, slower only for very
// sparse, widely spread scenes). A box lives in the cell of its lower corner,
// floor((lo - o) / s) with o the minimum lower corner, so overlapping boxes are in the
// same or adjacent cells; the engine (ccd/broad_phase/cell_grid.hpp) sorts the keys with
// a radix sort and scans each cell with a half-neighbourhood stencil (13 cells), so each
// pair is met once and nothing needs de-duplication. Per frame: O(n + candidate pairs);
// no allocation once the buffers have grown. Degrades when sizes vary widely (small
// boxes crowd into cells sized for the largest): use `hgrid` then.
// Boxes must be finite with lo <= hi; N = 0 or 1 gives no pairs.
//
// Frames in between (`reuse`, default 32): the pairs are found on boxes grown by about
// `reuse` frames of each body's motion and serve every following frame whose boxes all
// lie inside the grown ones, each listed pair box-tested (ccd/broad_phase/verlet_list.hpp;
// exact, the same pairs as a rebuild). stats().rebuilt tells the frames that rebuilt.
//
// Incremental update (update(), for the earliest scheduler): a batch of fewer than a
// quarter of the bodies moves only those bodies in a hashed grid kept between calls
// (ccd/broad_phase/cell_hash.hpp; cell size twice the mean largest box extent, chosen when
// it is built) and tests each moved box against the bodies listed in its cells: O(moved x cell
// occupancy), independent of N. A larger batch goes
// through the sorted grid, filtered (the hashed grid, once built, is kept current by every
// update; a find_pairs call in between makes it rebuild at the next small batch).
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/broad_phase/cell_grid.hpp>
#include <ccd/broad_phase/cell_hash.hpp>
#include <ccd/broad_phase/verlet_list.hpp>

namespace ccd {

struct GridOptions {
  /// Smallest cell size to use; 0 (the default) means "the largest box extent". A value
  /// below the largest extent is ignored (the neighbour rule would not hold).
  static constexpr double kCellSize = 0.0;
  double cell_size = kCellSize;
  /// Threads for one find_pairs call (1: serial, the registry's `grid`). With T > 1 the
  /// bounds pass, the keying, the gather and the neighbour-cell scan are split into T
  /// contiguous ranges (each of >= 16,384 bodies, else fewer threads), each thread with its own
  /// pair buffer, appended in range order: the pairs, and their order, are those of T = 1.
  static constexpr unsigned kThreads = 1;
  unsigned threads = kThreads;
  /// Frames one pair list, found on grown boxes, is meant to serve (0: rebuild every frame).
  static constexpr unsigned kReuse = detail::VerletList::kDefaultReuse;
  unsigned reuse = kReuse;
};

class UniformGrid final : public BroadPhase {
 public:
  explicit UniformGrid(GridOptions options = {}) : options_(options), verlet_(options.reuse) {}
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) override;
  void update(std::span<const Aabb> boxes, std::span<const std::uint32_t> moved, std::vector<BodyPair>& out) override;
  BroadPhaseStats stats() const override { return stats_; }
  /// Cell size used in the last call.
  double cell_size() const { return cell_; }

 private:
  void find_all(std::span<const Aabb> boxes, std::vector<BodyPair>& out);  // one rebuild's pass

  GridOptions options_;
  double cell_ = 0.0;
  detail::CellGrid cells_;
  BroadPhaseStats stats_;
  detail::VerletList verlet_;
  detail::CellHash hash_;      // the incremental update's grid
  bool hash_current_ = false;  // hash_ lists the boxes of the last call
  std::vector<std::uint32_t> seen_;   // per body: the last query that visited it
  std::vector<std::uint32_t> order_;  // per body: 1 + its place in `moved`, 0 if not moved
  std::uint32_t query_ = 0;
  std::vector<BodyPair> all_;  // a large batch's pairs before filtering
};

}  // namespace ccd
