#pragma once
// `hgrid`: hierarchical grid (Mirtich 1996; Ericson, Real-Time Collision Detection 7.2),
// rebuilt at every frame its Verlet list cannot serve. Exact: candidates get the
// closed-interval box test, so it reports the same pairs as `brute`.
//
// Levels: cell sizes s_h = s_top / 2^h, h = 0 (coarsest) .. h_max, where s_top is the
// `grid` rule (largest extent times 1 + 2^-20) and h_max the finest level that keeps at
// most 2^20 cells per axis and 2^32 per level. A body with largest extent e lives at the
// finest level with s_h >= e (1 + 2^-20), in the cell of its lower corner. Pairs: each
// level against itself (half stencil) and each finer level's bodies against the 27
// neighbour cells of their cell at every coarser non-empty level (engine:
// ccd/broad_phase/cell_grid.hpp). Per frame O(n * non-empty levels + candidates); sizes
// spanning many orders of magnitude cost one extra level each, where `grid` puts every
// small box into cells sized for the largest. Boxes must be finite with lo <= hi.
// Frames in between (`reuse`, default 32): a pair list found on grown boxes serves them,
// as in `grid` (ccd/broad_phase/verlet_list.hpp).
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/broad_phase/cell_grid.hpp>
#include <ccd/broad_phase/verlet_list.hpp>

#include <cstdint>

namespace ccd {

struct HgridOptions {
  /// Frames one pair list, found on grown boxes, is meant to serve (0: rebuild every frame).
  static constexpr unsigned kReuse = detail::VerletList::kDefaultReuse;
  unsigned reuse = kReuse;
};

class HierarchicalGrid final : public BroadPhase {
 public:
  explicit HierarchicalGrid(HgridOptions options = {}) : verlet_(options.reuse) {}
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) override;
  BroadPhaseStats stats() const override { return stats_; }
  /// Non-empty levels in the last call.
  std::size_t levels() const { return cell_.size(); }

 private:
  void find_all(std::span<const Aabb> boxes, std::vector<BodyPair>& out);  // one rebuild's pass

  detail::VerletList verlet_;
  std::vector<double> extent_;
  std::vector<std::uint8_t> halvings_;  // per body: h, then its engine level
  std::vector<double> cell_;            // non-empty levels, finest first
  detail::CellGrid cells_;
  BroadPhaseStats stats_;
};

}  // namespace ccd
