#pragma once
// `rtree`: the library baseline. Boost.Geometry's boost::geometry::index::rtree
// (quadratic split, 16 entries per node) bulk-loaded with its packing constructor every
// frame, then queried with each box (`intersects`, closed boxes: touching counts), keeping
// the partners with a larger index. Exact; no state kept between frames except buffers
// (the tree's own nodes are allocated by Boost each frame). Boxes must be finite.
#include <ccd/broad_phase/broad_phase.hpp>

#include <memory>

namespace ccd {

class BoostRtree final : public BroadPhase {
 public:
  BoostRtree();
  ~BoostRtree() override;
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) override;
  BroadPhaseStats stats() const override { return stats_; }

 private:
  struct Impl;  // keeps Boost.Geometry out of this header
  std::unique_ptr<Impl> impl_;
  BroadPhaseStats stats_;
};

}  // namespace ccd
