#pragma once
// Boxes around a body's shape for the orientation-aware bounds (frame_aabb, obb, obb_sat):
// the shape is its ConvexProxy (ccd/shape/convex_proxy.hpp), points grown by a radius, in
// the body frame whose origin is the centre of rotation. A body of kind Sphere is the ball
// of its enclosing radius about its centre.
#include <ccd/geometry/aabb.hpp>
#include <ccd/motion/rigid_motion.hpp>

#include <cstddef>

namespace ccd {

/// A box in the body frame: centre (not always the origin, e.g. for a hull) and half-widths.
struct LocalBox {
  Vec3 centre{Vec3::Zero()};
  Vec3 half{Vec3::Zero()};
};

/// The tightest body-frame box of `proxy`: the points' extremes on each body axis, grown
/// by the radius.
LocalBox local_box(const ConvexProxy& proxy);

/// The tightest world AABB of `proxy` turned by `rotation` (body to world) and placed at
/// `centre`: on each world axis k the extremes of (rotation p)_k over the points, grown by
/// the radius (the support of the shape along +/- e_k, in closed form).
Aabb rotated_box(const ConvexProxy& proxy, const Mat3& rotation, const Vec3& centre);

/// The orientation of `body` at time t (body to world): the identity when the scene has no
/// spinning shapes.
inline Mat3 body_rotation(const RigidMotion& motion, std::size_t body, double t) {
  return motion.rotations().empty() ? Mat3::Identity()
                                    : Mat3(motion.rotations().orientation(body, t).toRotationMatrix());
}

/// Grows a box by `d` on every side.
inline void grow(Aabb& box, double d) {
  box.lo.array() -= d;
  box.hi.array() += d;
}

}  // namespace ccd
