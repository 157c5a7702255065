#pragma once
// The scene's motion: what every stage may ask about a body (the bounds, the narrow
// phase, the schedulers, the runner and the ground truth all take this one object): its
// centre's exact trajectory (`centres()`), its shape (kind and ConvexProxy), its pose at a
// time (orientation from the prescribed or free spin), and a bound on the speed of its
// points. Always built, once per scene; for a scene of plain spheres it holds no rotations
// (every body is a ball about its centre) and `spheres()` says so, so that a stage decides
// once per step, not per pair, that the sphere x sphere path serves every pair.
#include <ccd/motion/rotation.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene.hpp>
#include <ccd/shape/convex_proxy.hpp>
#include <ccd/shape/shape_kind.hpp>

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

using Mat3 = Eigen::Matrix3d;

struct Pose {
  Vec3 centre{Vec3::Zero()};
  Mat3 rotation{Mat3::Identity()};  ///< body frame to world frame
  Vec3 apply(const Vec3& body_point) const { return centre + rotation * body_point; }
};

class RigidMotion {
 public:
  /// `centres` must outlive this object and be the trajectories of `scene`.
  RigidMotion(const Scene& scene, const Trajectories& centres);
  /// Every body of `centres` a ball of its radius, with no rotations (a scene of plain
  /// spheres). `centres` must outlive this object.
  explicit RigidMotion(const Trajectories& centres);
  /// No bodies yet (for assign_images, assign_spheres).
  RigidMotion() = default;
  /// Makes this the motion of `centres`' bodies as plain spheres (the constructor from
  /// trajectories, reusing this object's storage). `centres` must outlive this object's use.
  void assign_spheres(const Trajectories& centres);
  /// Makes this the motion of the local bodies of one step [t0, t1] of a scene that wraps
  /// around (pipeline/periodic_images.hpp): body i is `source`'s body owner[i] (its
  /// shape and spin; the spin pieces that overlap [t0, t1], so every query inside the step
  /// answers as `source`'s) with its centre on path i of `centres` (the body's unwrapped
  /// path or an image's). `centres` must outlive this object's use; storage is reused.
  void assign_images(const RigidMotion& source, const Trajectories& centres, std::span<const std::uint32_t> owner,
                     double t0, double t1);

  std::size_t size() const { return kinds_.size(); }
  /// true when every body is a ball of its enclosing radius about its centre and nothing
  /// spins (no shapes, no rotations): the sphere x sphere narrow entry answers every pair
  /// and every orientation-aware bound sees balls.
  bool spheres() const { return spheres_; }
  const Trajectories& centres() const { return *centres_; }
  const Rotations& rotations() const { return rotations_; }
  ShapeKind kind(std::size_t body) const { return kinds_[body]; }
  ConvexProxy proxy(std::size_t body) const;
  /// Radius of the ball about the centre that holds the body in every orientation.
  double enclosing_radius(std::size_t body) const { return centres_->radius(body); }
  Pose pose(std::size_t body, double t) const;
  /// Bound on the distance between the evaluated and the exact position of any point of
  /// `body` at t (metres): the orientation's evaluation error (a free spin's closed form,
  /// ccd/motion/free_rotation.hpp; 0 for constant spins) times the body's reach.
  double pose_error(std::size_t body, double t) const {
    return rotations_.empty() ? 0.0 : rotations_.orientation_error(body, t) * centres_->radius(body);
  }
  /// Upper bound on the speed of every point of `body` over [u0, u1] (m/s):
  /// max |centre velocity| (at the ends of each trajectory piece inside, where |v + a s|
  /// is largest) + max |omega| x enclosing radius, rounded up.
  double max_point_speed(std::size_t body, double u0, double u1) const;

 private:
  const Trajectories* centres_ = nullptr;
  Rotations rotations_;
  std::vector<ShapeKind> kinds_;
  std::vector<std::vector<Vec3>> points_;  ///< per shape of the scene, then one origin
  std::vector<std::uint32_t> point_set_;   ///< per body: index into points_
  std::vector<double> proxy_radius_;       ///< per body
  bool spheres_ = true;
  void classify();  ///< sets spheres_ from the kinds and rotations
};

}  // namespace ccd
