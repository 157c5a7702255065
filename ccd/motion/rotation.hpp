#pragma once
// Prescribed orientations of a scene's bodies over [0, horizon] (docs/rigid_bodies.md).
//
// A body's angular velocity omega is given in the world frame and is constant between
// its changes (prescribed spin: no torque, no inertia, no collision response). On a
// piece [t0, t1] the orientation is
//     q(t) = exp((t - t0) omega / 2) q0,
// the rotation by the angle |omega| (t - t0) about omega / |omega| applied after q0. A
// piece starts at 0 and at each angular-velocity change; a later piece's q0 is the
// earlier piece evaluated at the change and normalised: the model is defined by these
// stored quaternions, so a change carries no error of its own. Walls do not change the
// spin (they act on the centre only, ccd/motion/trajectory.hpp).
//
// A body with `"spin": "free"` has torque-free pieces instead (ccd/motion/free_rotation.hpp):
// on each, the world angular momentum is constant and the orientation is the Euler-Poinsot
// closed form; at an angular-velocity change the new piece starts from the old piece's
// orientation with the given angular velocity (an impulse: L jumps). `omega` of such a
// piece is the angular velocity at t0 only; what a bound may use is `max_rate()`.
//
// Rotations is empty for a scene without non-sphere shapes: the orientation of a sphere
// never matters, and sphere scenes pay nothing.
#include <ccd/geometry/vec3.hpp>
#include <ccd/motion/free_rotation.hpp>
#include <ccd/scene/scene.hpp>

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace ccd {

using Quat = Eigen::Quaterniond;

struct RotationPiece {
  double t0 = 0.0;
  double t1 = 0.0;
  Quat q0{Quat::Identity()};
  Vec3 omega{Vec3::Zero()};  ///< world frame, rad/s (a free piece: at t0)
  /// Torque-free piece, or null (constant omega).
  std::shared_ptr<const FreeRotation> free;

  /// q(t) for t in [t0, t1] (any t: the formula extrapolates), unit.
  Quat orientation(double t) const;
  /// The angular velocity is `omega` over the whole piece.
  bool constant_spin() const { return !free || free->constant(); }
  /// An upper bound on |omega(t)| over the piece (rad/s).
  double max_rate() const { return free ? free->max_omega() : omega.norm(); }
  /// Bound on the evaluation error of orientation(t) (radians; 0 for constant omega).
  double orientation_error(double t) const { return free ? free->orientation_error(t) : 0.0; }
};

class Rotations {
 public:
  Rotations() = default;
  /// Every body's pieces when the scene has a non-sphere shape; empty otherwise.
  explicit Rotations(const Scene& scene);

  bool empty() const { return first_.size() <= 1; }
  std::size_t size() const { return first_.size() - 1; }
  std::span<const RotationPiece> pieces(std::size_t body) const {
    return {pieces_.data() + first_[body], pieces_.data() + first_[body + 1]};
  }
  /// The piece of `body` that holds time t (the later one at a change).
  const RotationPiece& piece_at(std::size_t body, double t) const;
  Quat orientation(std::size_t body, double t) const { return piece_at(body, t).orientation(t); }
  /// max |omega| of `body` over [u0, u1] (rad/s; an upper bound for free pieces).
  double max_omega(std::size_t body, double u0, double u1) const;
  /// Bound on the evaluation error of orientation(body, t) (radians).
  double orientation_error(std::size_t body, double t) const { return piece_at(body, t).orientation_error(t); }
  /// Makes body i of this set turn as body owner[i] of `source`, keeping only the pieces
  /// that overlap [t0, t1]: every query inside [t0, t1] answers as `source`'s does (the
  /// bodies and periodic images of one step, pipeline/periodic_images.hpp). Empty when
  /// `source` is. Reuses the storage.
  void assign_owners(const Rotations& source, std::span<const std::uint32_t> owner, double t0, double t1);
  /// Empty again (no bodies turn), keeping the storage.
  void clear() {
    pieces_.clear();
    first_.assign(1, 0);
  }

 private:
  std::vector<RotationPiece> pieces_;
  std::vector<std::uint32_t> first_{0};
};

}  // namespace ccd
