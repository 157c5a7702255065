#pragma once
// `horn:M` (Knowledge::Bounded, default M = 4): Hubbard's parabolic horn. A body with
// position p and velocity v at t0 and |acceleration| <= A (ctx.acceleration_bound) has its
// centre within A s^2 / 2 of p + v s, s = t - t0, so the body lies in the sphere of centre
// p + v s and radius r + A s^2 / 2. The horn is covered by M axis-aligned hyper-trapezoids
// over equal sub-intervals of [t0, t1] (bounds/trapezoid.hpp; slack at most A (h/M)^2 / 8
// per sub-interval). Box: the hull of the trapezoids.
// Pair test: trapezoid_overlap on each sub-interval in time order (the faces move
// linearly: six half-lines in time); true at the first sub-interval where the two
// trapezoids overlap, with `earliest` = the earliest time of overlap (no contact is
// possible before it while the bound's assumption holds). O(M) per pair, no allocation.
// Static test: each sub-interval's trapezoid (its hull: a static polygon does not move)
// against the polygon by separating axes (ccd/queries/aabb_polygon.hpp: the polygon's
// normal, the box axes, their cross products with the edges), in time order; Possible at
// the first that meets it, `earliest` = that sub-interval's start.
// Walls: a reflection is an unbounded acceleration, so an axis of a sub-interval on which
// the horn's centre may pass a wall plane uses the static folded interval of that
// sub-interval (bounds/wall_fold.hpp): conservative across reflections, looser there.
// Guarantee: conservative whenever |acceleration| <= A over the step (walls included).
// Refresh: one body's trapezoids over its own window. Bodies over different windows are
// compared by trapezoid_sequence_overlap (split at the union of both bodies' breakpoints).
// M = 4 by default: slack A h^2 / 128, a quarter of the pair cost of M = 8.
#include <bounds/bound.hpp>
#include <bounds/trapezoid.hpp>

namespace ccd {

class HornBound final : public Bound {
 public:
  static constexpr int default_pieces = 4;
  explicit HornBound(int pieces = default_pieces);
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  PairTest test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                       const Aabb& polygon_box) const override;
  void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) override;
  Window window(std::uint32_t body) const override {
    const Trapezoid* z = traps_.data() + std::size_t{body} * m_;
    return {z[0].t0, z[m_ - 1].t1};
  }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;
  int pieces() const { return m_; }
  /// Trapezoid j (sub-interval j, 0 <= j < M) of `body` from the last prepare.
  const Trapezoid& trapezoid(std::uint32_t body, int j) const { return traps_[std::size_t{body} * m_ + j]; }

 private:
  Aabb build(const StepContext& ctx, std::size_t i);
  int m_;
  std::vector<Trapezoid> traps_;
};

}  // namespace ccd
