#include <ccd/motion/rigid_motion.hpp>

#include <algorithm>
#include <limits>

namespace ccd {

RigidMotion::RigidMotion(const Scene& scene, const Trajectories& centres)
    : centres_(&centres), rotations_(scene) {
  for (const Shape& s : scene.shapes) points_.push_back(s.points);
  const auto origin = static_cast<std::uint32_t>(points_.size());
  points_.push_back({Vec3::Zero()});
  kinds_.reserve(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const std::int32_t shape = scene.rigid.empty() ? kNoShape : scene.rigid[i].shape;
    kinds_.push_back(scene.kind(i));
    if (shape == kNoShape) {
      point_set_.push_back(origin);
      proxy_radius_.push_back(scene.bodies[i].radius);
    } else {
      const Shape& s = scene.shapes[static_cast<std::size_t>(shape)];
      point_set_.push_back(static_cast<std::uint32_t>(shape));
      proxy_radius_.push_back(s.proxy().radius);
    }
  }
  classify();
}

// A body of kind Sphere is the ball of its radius about its centre (its proxy is the one
// point at the origin: ccd/shape/shape.hpp), the radius its enclosing radius.
void RigidMotion::classify() {
  spheres_ = rotations_.empty() &&
             std::all_of(kinds_.begin(), kinds_.end(), [](ShapeKind k) { return k == ShapeKind::Sphere; });
}

RigidMotion::RigidMotion(const Trajectories& centres) { assign_spheres(centres); }

void RigidMotion::assign_spheres(const Trajectories& centres) {
  centres_ = &centres;
  rotations_.clear();
  points_.resize(1);
  points_[0].assign(1, Vec3::Zero());
  kinds_.assign(centres.size(), ShapeKind::Sphere);
  point_set_.assign(centres.size(), 0);
  proxy_radius_.clear();
  for (std::size_t i = 0; i < centres.size(); ++i) proxy_radius_.push_back(centres.radius(i));
  spheres_ = true;
}

void RigidMotion::assign_images(const RigidMotion& source, const Trajectories& centres,
                                std::span<const std::uint32_t> owner, double t0, double t1) {
  centres_ = &centres;
  points_ = source.points_;  // element-wise: no allocation once the sizes are reached
  rotations_.assign_owners(source.rotations_, owner, t0, t1);
  kinds_.clear();
  point_set_.clear();
  proxy_radius_.clear();
  for (const std::uint32_t o : owner) {
    kinds_.push_back(source.kinds_[o]);
    point_set_.push_back(source.point_set_[o]);
    proxy_radius_.push_back(source.proxy_radius_[o]);
  }
  spheres_ = source.spheres_;
}

ConvexProxy RigidMotion::proxy(std::size_t body) const {
  return {points_[point_set_[body]], proxy_radius_[body]};
}

Pose RigidMotion::pose(std::size_t body, double t) const {
  Pose p;
  p.centre = centres_->position(body, t);
  if (!rotations_.empty()) p.rotation = rotations_.orientation(body, t).toRotationMatrix();
  return p;
}

double RigidMotion::max_point_speed(std::size_t body, double u0, double u1) const {
  double v = 0.0;
  for (const Piece& q : centres_->pieces(body)) {
    if (q.t1 < u0 || q.t0 > u1) continue;
    v = std::max({v, q.velocity(std::max(u0, q.t0)).norm(), q.velocity(std::min(u1, q.t1)).norm()});
  }
  const double w = rotations_.empty() ? 0.0 : rotations_.max_omega(body, u0, u1);
  // Norms, products and the sum are each within a few ulps: 16 ulps above is above exact.
  return (v + w * enclosing_radius(body)) * (1.0 + 16.0 * std::numeric_limits<double>::epsilon());
}

}  // namespace ccd
