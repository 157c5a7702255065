#pragma once
// `capsule` (Knowledge::Exact): the swept sphere as a capsule: the segment S from p(t0) to
// p(t1) (the chord of the centre's path over the step) with radius r + e, where e covers
// the path's distance from the chord:
// - one quadratic piece over the step (no reflection, no acceleration change): the path
//   deviates from its chord by at most |a| h^2 / 8 (ccd-math §5), so e = |a| h^2 / 8
//   (e = 0 for linear motion: the exact swept sphere);
// - several pieces (a wall reflection or an acceleration change inside the step): S is
//   still the chord of the whole step, and e = max over pieces k of
//   max(dist(q_k, S), dist(q_k+1, S)) + |a_k| h_k^2 / 8, with q_k, q_k+1 the piece's end
//   points and h_k its duration inside the step: each piece stays within |a_k| h_k^2 / 8
//   of its own chord, and every point of that chord is within the larger end-point
//   distance of S (distance to a convex set is convex along a segment). Conservative but
//   loose for a reflection in the middle of the step (e ~ the distance travelled to the
//   wall); the swept box below keeps broad-phase culling tight.
// Box: the capsule's AABB intersected with the exact swept box (Trajectories::swept_bounds),
// both of which contain the body. Pair test: segment-segment distance (ccd/queries/
// segment_segment.hpp) <= r1 + r2 (squared compare, with the rounding slack of rounding.hpp
// on the radii and 16 ulps of |d1|^2 + |d2|^2 + |p1 - p2|^2 for the closest-pair error).
// Static test: segment-polygon distance (ccd/queries/segment_polygon.hpp) <= the capsule's
// radius (with the polygon queries' slack, rounding.hpp).
// Conservative. `earliest`: a capsule carries no timing, so it comes from speed bounds
// (bounds/speed_earliest.hpp: centre at the window's start, largest speed in the window). Refresh: one body's capsule over its own window.
#include <bounds/bound.hpp>
#include <bounds/speed_earliest.hpp>

namespace ccd {

class CapsuleBound final : public Bound {
 public:
  struct Capsule {
    Vec3 p0;        ///< centre at t0
    Vec3 p1;        ///< centre at t1
    double radius;  ///< r + e + slack
    double speed;   ///< largest speed over the window
    double body_radius;
  };
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  /// `test` pair by pair, fetching the capsules of the pairs a few places ahead.
  void test_pairs(std::span<const BodyPair> pairs, std::vector<BodyPair>& passed,
                  std::vector<double>& earliest) const override;
  PairTest test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                       const Aabb& polygon_box) const override;
  void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) override;
  Window window(std::uint32_t body) const override { return windows_[body]; }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;
  const Capsule& capsule(std::uint32_t body) const { return capsules_[body]; }

 private:
  Aabb build(const StepContext& ctx, std::size_t i);
  std::vector<Capsule> capsules_;
  std::vector<Window> windows_;
};

}  // namespace ccd
