// Boxes around shapes (bounds/shape_boxes.hpp): the body-frame box and the turned shape's
// world box are tight (attained by the shape) and hold every point of the shape; the world
// box matches the closed forms |R| h (box) and |R e_x| L + r (capsule).
#include <bounds/shape_boxes.hpp>
#include <ccd/shape/shape.hpp>
#include <tests/bounds/rigid_bound_support.hpp>

#include <catch2/catch.hpp>
#include <random>

namespace bounds_shape_boxes_test {

using ccd::Vec3;

namespace {

/// A random point of the shape: a convex combination of its points plus a vector of length
/// <= its radius.
Vec3 random_point(std::mt19937_64& rng, const ccd::ConvexProxy& p) {
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  Vec3 x = Vec3::Zero();
  double total = 0.0;
  for (const Vec3& q : p.points) {
    const double w = u(rng);
    x += w * q;
    total += w;
  }
  x /= total;
  Vec3 d(s(rng), s(rng), s(rng));
  if (d.norm() > 1.0) d /= d.norm();
  return x + p.radius * d;
}

bool inside(const ccd::Aabb& b, const Vec3& x, double tol) {
  return (b.lo.array() - tol <= x.array()).all() && (x.array() <= b.hi.array() + tol).all();
}

}  // namespace

TEST_CASE("shape boxes hold the shape and are tight", "[bounds][obb]") {
  ccd::Scene s;
  ccd::test::add_test_shapes(s);
  s.shapes.push_back(ccd::make_sphere_shape(0.375));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const ccd::Shape& shape : s.shapes) {
    INFO(shape.name);
    const ccd::ConvexProxy p = shape.proxy();
    const ccd::LocalBox local = ccd::local_box(p);
    for (int k = 0; k < 200; ++k) {
      ccd::Quat q(u(rng), u(rng), u(rng), u(rng));
      q.normalize();
      const ccd::Mat3 r = k < 8 ? ccd::Mat3(ccd::test::exact_orientations()[k].toRotationMatrix())
                                : ccd::Mat3(q.toRotationMatrix());
      const Vec3 c = k % 2 ? Vec3(1048576, 0.5, -3) : Vec3(0.25, 0.5, 0.75);
      const ccd::Aabb world = ccd::rotated_box(p, r, c);
      // Closed forms.
      if (shape.kind == ccd::ShapeKind::Box) {
        const Vec3 e = r.cwiseAbs() * shape.half_extents;
        CHECK(((world.hi - c) - e).cwiseAbs().maxCoeff() <= 1e-12 * (1 + c.norm()));
        CHECK(((c - world.lo) - e).cwiseAbs().maxCoeff() <= 1e-12 * (1 + c.norm()));
      }
      if (shape.kind == ccd::ShapeKind::Capsule) {
        const Vec3 e = (r.col(0).cwiseAbs() * shape.half_length).array() + shape.radius;
        CHECK(((world.hi - c) - e).cwiseAbs().maxCoeff() <= 1e-12 * (1 + c.norm()));
      }
      // Every point inside; each face of the box attained by a support point of the shape.
      for (int j = 0; j < 50; ++j) {
        const Vec3 x = random_point(rng, p);
        CHECK(inside(world, c + r * x, 1e-12 * (1 + c.norm())));
        CHECK(inside({local.centre - local.half, local.centre + local.half}, x, 1e-15));
      }
      for (int axis = 0; axis < 3; ++axis) {
        for (const double sign : {-1.0, 1.0}) {
          const Vec3 d = sign * r.transpose().col(axis);  // world axis in the body frame
          const Vec3 support = p.points[p.support_index(d)] + p.radius * d;
          const double reached = (c + r * support)[axis];
          CHECK(reached == Approx(sign > 0 ? world.hi[axis] : world.lo[axis]).margin(1e-12 * (1 + c.norm())));
        }
      }
    }
  }
}

}  // namespace bounds_shape_boxes_test
