#include <ccd/motion/rotation.hpp>

#include <algorithm>
#include <cmath>

namespace ccd {

Quat RotationPiece::orientation(double t) const {
  const double w = omega.norm();
  if (w == 0.0) return q0;
  const double half = 0.5 * w * (t - t0);
  const Vec3 axis = omega / w;
  const Quat step(std::cos(half), std::sin(half) * axis.x(), std::sin(half) * axis.y(), std::sin(half) * axis.z());
  return (step * q0).normalized();
}

Rotations::Rotations(const Scene& scene) {
  if (!scene.has_non_spheres()) return;
  first_.reserve(scene.bodies.size() + 1);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const RigidBody b = scene.rigid_body(i);
    RotationPiece piece;
    piece.t0 = 0.0;
    piece.q0 = b.orientation;
    piece.omega = b.angular_velocity;
    for (const AngularVelocityChange& c : b.angular_velocity_changes) {
      piece.t1 = c.t;
      pieces_.push_back(piece);
      RotationPiece next;
      next.t0 = c.t;
      next.q0 = piece.orientation(c.t);
      next.omega = c.angular_velocity;
      piece = next;
    }
    piece.t1 = scene.horizon;
    pieces_.push_back(piece);
    first_.push_back(static_cast<std::uint32_t>(pieces_.size()));
  }
}

const RotationPiece& Rotations::piece_at(std::size_t body, double t) const {
  const auto ps = pieces(body);
  // The last piece with t0 <= t (the later one at a change).
  auto it = std::upper_bound(ps.begin(), ps.end(), t, [](double x, const RotationPiece& p) { return x < p.t0; });
  return it == ps.begin() ? ps.front() : *(it - 1);
}

double Rotations::max_omega(std::size_t body, double u0, double u1) const {
  double m = 0.0;
  for (const RotationPiece& p : pieces(body))
    if (p.t1 >= u0 && p.t0 <= u1) m = std::max(m, p.omega.norm());
  return m;
}

}  // namespace ccd
