#pragma once
// Internal engine of `grid` and `hgrid`: sorted cell lists over one or more grid levels.
// Not a broad phase itself; UniformGrid and HierarchicalGrid choose the cell sizes and
// each body's level, this file does the rest.
//
// Cells. Level l has cell size s_l and shares the origin o (the minimum box lo corner) with
// every level. A body lives in the cell of its LOWER CORNER, c = floor((lo - o) / s_l) per
// axis, at its own level. Cells are keyed row-major, key = ix + nx (iy + ny iz), with one
// empty padding column (ix = nx - 1) and row (iy = ny - 1), so a neighbour offset never
// wraps onto a real cell; keys are below 2^32 by contract and relative to o, so they are
// never negative (no hashing, no modulo, no collisions).
//
// Why neighbours suffice. Callers guarantee s_l >= (1 + 2^-20) * extent of every body at
// level l or finer, and at most 2^20 cells per axis. If boxes A and B overlap then
// |lo_A - lo_B| <= max(extent_A, extent_B) on each axis, so their cells at the coarser of
// their two levels differ by at most one per axis; the 2^-20 slack absorbs the rounding
// of (lo - o) / s (relative error < 2^-50 on indices below 2^20).
//
// Pairs. Per level, bodies are sorted by (key, body) with an LSD radix sort on the key bits
// in use and copied in that order (48-byte boxes; ids apart, read only on hits).
// Same level: each cell against itself and the 13 neighbours of a half stencil
// (+x; the 3 cells of row y+1; the 9 cells of plane z+1), found with 4 monotone cursors
// over the sorted cell keys (one per stencil row), so every unordered pair of cells is met
// once. Across levels: the bodies of a finer level are keyed by their cell at each
// coarser non-empty level, radix-sorted, and merged with that level's cells by 9 monotone
// cursors (the 27-cell neighbourhood), so a pair of bodies on different levels is met
// once, from the finer body. Every candidate pair gets the exact closed-interval box test.
// When a level has at most kMaxOccupancyCells cells and at most 64 per body, the 4 cursors
// are replaced by an occupancy bitmap of the level's cells with per-word ranks: a stencil
// row is 3 bits at its first key, mostly zero, and the first occupied cell's index is the
// rank, with no data-dependent cursor loops (the scan was half the time at 1e6 bodies).
//
// Threads (set_threads, default 1). With T > 1 threads the keying, the radix sort's
// passes (per-chunk digit counts, offsets laid out by digit then chunk, per-chunk scatter:
// the serial result), the gather, the occupancy bitmap (each thread owns the whole words
// of a range of sorted cells, and its ranks start at its first cell's index) and the
// same-level scan split their index or cell ranges into T contiguous pieces of about equal
// body counts (only while each piece keeps >= kMinBodiesPerThread bodies); each thread
// writes its own pair buffer and the buffers are appended in range order, so the pairs
// come out in exactly the serial order whatever T is. The cross-level merge stays serial.
// The threads come from a persistent pool (ccd/util/parallel_for.hpp, about a microsecond
// a call); the minimum piece keeps the split worth its memory traffic.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/util/parallel_for.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace ccd::detail {

/// Cells per axis (with padding) and total cells of a level; saturates above 2^40 total.
struct CellShape {
  std::uint64_t nx = 3, ny = 3, nz = 1;
  std::uint64_t cells() const;
};

/// Relative slack on cell sizes that absorbs index rounding (see the header comment).
inline constexpr double kCellSlack = 0x1p-20;
/// Most cells per axis and per level.
inline constexpr double kMaxCellsPerAxis = 0x1p20;
inline constexpr std::uint64_t kMaxCellsPerLevel = std::uint64_t{1} << 32;
/// Largest level (cells) scanned with an occupancy bitmap (8 MB) instead of cursors.
inline constexpr std::uint64_t kMaxOccupancyCells = std::uint64_t{1} << 26;
/// Smallest level (bytes of its items) whose bitmap scan prefetches the boxes of the next
/// plane's rows: 1 MiB, about a core's L2 cache (21,845 items).
inline constexpr std::uint64_t kPrefetchItemBytes = std::uint64_t{1} << 20;
/// Fewest bodies per thread for a parallel piece of work.
inline constexpr std::size_t kMinBodiesPerThread = 16384;

/// Threads to use for `items` units of work with at most `threads` threads.
unsigned threads_for(std::size_t items, unsigned threads);

/// The shape of a level of cell size `cell` over lower corners in [o, o + span].
CellShape cell_shape(double cell, const std::array<double, 3>& span);

/// Smallest cell size >= `wanted` (>= 0) that respects the per-axis and per-level limits;
/// 1 when everything is zero.
double admissible_cell(double wanted, const std::array<double, 3>& span);

class CellGrid {
 public:
  /// Builds the cell lists. `cell[l]` is level l's cell size, finest first (strictly
  /// increasing); `level[i]` is body i's level (empty span: all on level 0). `origin` is the
  /// componentwise minimum of the lower corners, `span` the maximum lower corner minus it.
  void build(std::span<const Aabb> boxes, std::span<const std::uint8_t> level, std::span<const double> cell,
             const std::array<double, 3>& origin, const std::array<double, 3>& span);
  /// Appends every overlapping pair (a < b) once; returns the number of box tests.
  std::uint64_t find_pairs(std::vector<BodyPair>& out);
  /// Threads for build() and find_pairs(); 0 and 1 mean serial. See the header comment.
  void set_threads(unsigned threads) { threads_ = threads < 1 ? 1 : threads; }
  unsigned threads() const { return threads_; }

  struct Item {
    double lo[3];
    double hi[3];
  };

 private:
  struct Level {
    double inv = 1.0;  // 1 / cell size
    CellShape shape;
    std::uint32_t begin = 0, end = 0;            // items [begin, end)
    std::uint32_t cell_begin = 0, cell_end = 0;  // cells [cell_begin, cell_end)
    int key_bits = 0;
  };
  std::uint64_t key_of(const Level& lv, const double lo[3]) const;
  std::uint64_t same_level(const Level& lv, std::vector<BodyPair>& out);
  void build_occupancy(const Level& lv);
  std::uint64_t same_level_cells(const Level& lv, std::uint32_t c_begin, std::uint32_t c_end,
                                 std::vector<BodyPair>& out) const;
  std::uint64_t cross_level(const Level& fine, const Level& coarse, std::vector<BodyPair>& out);

  std::array<double, 3> origin_{};
  std::vector<Level> levels_;
  std::vector<std::uint64_t> packed_, tmp_;  // (key << 32) | body, sorted per level
  std::vector<std::uint64_t> query_;         // cross-level queries: (coarse key << 32) | item
  std::vector<Item> items_;                  // boxes in sorted order (48 bytes each)
  std::vector<std::uint32_t> ids_;           // their body ids
  std::vector<std::uint32_t> cell_key_;      // per cell, levels one after another
  std::vector<std::uint32_t> cell_start_;    // first item of each cell, + sentinel
  std::vector<std::uint64_t> occupied_;       // occupancy bitmap of the level being scanned
  std::vector<std::uint32_t> rank_;           // occupied cells before each bitmap word
  bool bitmap_ = false;                       // whether that level is scanned by the bitmap
  unsigned threads_ = 1;
  struct ThreadBuffers {  // for threads 1.. (thread 0 writes the shared outputs directly)
    std::vector<BodyPair> pairs;
    std::vector<std::uint32_t> cell_key, cell_start;
  };
  std::vector<ThreadBuffers> thread_;
};

}  // namespace ccd::detail
