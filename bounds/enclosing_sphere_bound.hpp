#pragma once
// `enclosing_sphere` (Knowledge::Bounded): one static sphere around the body's whole horn
// over the step (h = t1 - t0, |acceleration| <= A). The centre at s lies within A s^2 / 2 of
// p + v s; for a centre C = p + v c on the line, the largest distance from C to the horn's
// centre region is max over s in [0, h] of |v| |s - c| + A s^2 / 2, a convex function of s
// whose maximum is at s = 0 or s = h. Balancing the two ends gives the smallest such sphere:
//   A h < 2 |v|:  c = h/2 + A h^2 / (4 |v|),  radius r + |v| h / 2 + A h^2 / 4
//   A h >= 2 |v|: c = h,                      radius r + A h^2 / 2
// (tighter than r + |v| h / 2 + A h^2 / 2 about p + v h / 2, and than r + |v| h + A h^2 / 2
// about p). Box: the sphere's AABB. Test: centre distance <= sum of radii (squared compare).
// Walls: a body whose sphere of centres reaches a wall plane (min + r, max - r) may reflect;
// it is replaced by its box, folded into the walls per axis (bounds/wall_fold.hpp), and the
// pair test becomes sphere-box (squared distance from the centre to the box) or box-box.
// Static test: distance from the sphere's centre to the polygon <= its radius; a boxed body:
// its box against the polygon by separating axes (ccd/queries/aabb_polygon.hpp).
// Conservative whenever |acceleration| <= A (walls included). `earliest`: a static sphere
// carries no timing, so it comes from speed bounds (bounds/speed_earliest.hpp: the centre
// at the window's start, speed <= |v| + A h over the window). Refresh: one body's sphere over
// its own window.
#include <bounds/bound.hpp>
#include <bounds/speed_earliest.hpp>

namespace ccd {

class EnclosingSphereBound final : public Bound {
 public:
  struct Shape {
    Vec3 centre;
    double radius;  ///< r + the centre region's radius + slack
    bool boxed;     ///< folded at a wall: the shape is `box` instead of the sphere
    Aabb box;
    SpeedBall ball;  ///< for `earliest`
  };
  void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) override;
  PairTest test(std::uint32_t a, std::uint32_t b) const override;
  PairTest test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                       const Aabb& polygon_box) const override;
  void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes) override;
  Window window(std::uint32_t body) const override { return windows_[body]; }
  void volumes(std::uint32_t body, std::vector<Volume>& out) const override;
  const Shape& shape(std::uint32_t body) const { return shapes_[body]; }

 private:
  Aabb build(const StepContext& ctx, std::size_t i);
  std::vector<Shape> shapes_;
  std::vector<Window> windows_;
};

}  // namespace ccd
