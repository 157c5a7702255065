#include <bounds/enclosing_sphere_bound.hpp>
#include <bounds/rounding.hpp>
#include <bounds/wall_fold.hpp>
#include <ccd/queries/aabb_polygon.hpp>
#include <ccd/queries/point_polygon.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

double box_point_distance_squared(const Aabb& box, const Vec3& x) {
  const Vec3 d = (box.lo - x).cwiseMax(x - box.hi).cwiseMax(Vec3::Zero());
  return d.squaredNorm();
}

}  // namespace

Aabb EnclosingSphereBound::build(const StepContext& ctx, std::size_t i) {
  const double h = ctx.t1 - ctx.t0;
  const double A = ctx.acceleration_bound;
  const BodyState& s = ctx.start[i];
  const double speed = s.velocity.norm();
  double c = h;
  double rc = 0.5 * A * h * h;  // radius of the centre region
  if (A * h < 2.0 * speed) {
    c = 0.5 * h + A * h * h / (4.0 * speed);
    rc = 0.5 * speed * h + 0.25 * A * h * h;
  }
  const Vec3 centre = s.position + s.velocity * c;
  const double slack =
      rounding_slack(s.position.cwiseAbs().maxCoeff() + s.radius + s.velocity.cwiseAbs().maxCoeff() * h + A * h * h);
  rc += slack;
  Shape& sh = shapes_[i];
  sh.centre = centre;
  sh.radius = s.radius + rc;
  sh.boxed = false;
  sh.ball = {s.position, ctx.t0, (speed + A * h) * (1.0 + 8.0 * std::numeric_limits<double>::epsilon()), s.radius};
  sh.box = Aabb::around(centre, sh.radius);
  if (ctx.walls) {
    for (int k = 0; k < 3; ++k) {
      const double L = ctx.walls->min[k] + s.radius;
      const double H = ctx.walls->max[k] - s.radius;
      if (L <= H && (centre[k] - rc < L || centre[k] + rc > H)) {
        const Interval f = fold_interval(centre[k] - rc, centre[k] + rc, L, H);
        sh.box.lo[k] = f.lo - s.radius - slack;
        sh.box.hi[k] = f.hi + s.radius + slack;
        sh.boxed = true;
      }
    }
  }
  return sh.box;
}

void EnclosingSphereBound::prepare(const StepContext& ctx, std::vector<Aabb>& boxes) {
  const std::size_t n = ctx.start.size();
  shapes_.resize(n);
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = build(ctx, i);
  windows_.assign(n, Window{ctx.t0, ctx.t1});
}

void EnclosingSphereBound::refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies,
                                   std::span<Aabb> boxes) {
  if (shapes_.size() != ctx.start.size()) {  // no prepare before: room for every body
    shapes_.resize(ctx.start.size());
    windows_.resize(ctx.start.size());
  }
  for (const std::uint32_t i : bodies) {
    boxes[i] = build(ctx, i);
    windows_[i] = {ctx.t0, ctx.t1};
  }
}

PairTest EnclosingSphereBound::test(std::uint32_t a, std::uint32_t b) const {
  const Window w = common_window(windows_[a], windows_[b]);
  if (w.t0 > w.t1) return PairTest::disjoint();
  const Shape& x = shapes_[a];
  const Shape& y = shapes_[b];
  bool hit;
  if (!x.boxed && !y.boxed) {
    const double R = x.radius + y.radius;
    hit = (x.centre - y.centre).squaredNorm() <= R * R;
  } else if (x.boxed && y.boxed) {
    hit = x.box.overlaps(y.box);
  } else {
    const Shape& ball = x.boxed ? y : x;
    const Shape& box = x.boxed ? x : y;
    hit = box_point_distance_squared(box.box, ball.centre) <= ball.radius * ball.radius;
  }
  if (!hit) return PairTest::disjoint();
  return PairTest::possible_from(std::min(speed_earliest(x.ball, y.ball), w.t1));
}

PairTest EnclosingSphereBound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                                           const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  const Shape& x = shapes_[body];
  if (x.boxed) {
    if (!aabb_polygon_overlap(x.box, polygon, aabb_polygon_rounding(x.box, polygon))) return PairTest::disjoint();
  } else {
    const double R = x.radius + static_rounding_slack(x.centre, polygon);
    if (point_polygon_closest(x.centre, polygon).distance_squared > R * R) return PairTest::disjoint();
  }
  const double d = std::sqrt(point_polygon_closest(x.ball.centre, polygon).distance_squared);
  return PairTest::possible_from(std::min(
      speed_earliest_static(x.ball, d, static_rounding_slack(x.ball.centre, polygon)), windows_[body].t1));
}

void EnclosingSphereBound::volumes(std::uint32_t body, std::vector<Volume>& out) const {
  const Shape& s = shapes_[body];
  const Window w = windows_[body];
  out.push_back(s.boxed ? Volume::box(s.box, w.t0, w.t1) : Volume::sphere(s.centre, s.radius, w.t0, w.t1));
}

}  // namespace ccd
