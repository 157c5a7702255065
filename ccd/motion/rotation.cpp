#include <ccd/motion/rotation.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

namespace ccd {

Quat RotationPiece::orientation(double t) const {
  if (free) return free->orientation(t);
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
  // Free bodies of one shape and one mass or density share their principal inertia: a
  // hull's is computed once (points x faces time), not once per body.
  std::map<std::tuple<int, double, double>, std::pair<Vec3, Eigen::Matrix3d>> shared;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const RigidBody b = scene.rigid_body(i);
    Vec3 moments = Vec3::Ones();
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    if (b.spin == SpinModel::Free) {
      if (b.shape != kNoShape && !b.inertia) {
        const auto key = std::tuple(static_cast<int>(b.shape), b.mass.value_or(-1.0), b.density.value_or(-1.0));
        auto it = shared.find(key);
        if (it == shared.end()) {
          scene.principal_inertia(i, moments, axes);
          it = shared.emplace(key, std::pair(moments, axes)).first;
        }
        std::tie(moments, axes) = it->second;
      } else {
        scene.principal_inertia(i, moments, axes);
      }
    }
    auto start = [&](double t0, const Quat& q0, const Vec3& omega) {
      RotationPiece p;
      p.t0 = t0;
      p.q0 = q0;
      p.omega = omega;
      if (b.spin == SpinModel::Free && !omega.isZero(0.0))
        p.free = std::make_shared<const FreeRotation>(moments, axes, q0, omega, t0);
      return p;
    };
    RotationPiece piece = start(0.0, b.orientation, b.angular_velocity);
    for (const AngularVelocityChange& c : b.angular_velocity_changes) {
      piece.t1 = c.t;
      pieces_.push_back(piece);
      piece = start(c.t, piece.orientation(c.t), c.angular_velocity);
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

void Rotations::assign_owners(const Rotations& source, std::span<const std::uint32_t> owner, double t0, double t1) {
  pieces_.clear();
  first_.assign(1, 0);
  if (source.empty()) return;
  for (const std::uint32_t o : owner) {
    const auto ps = source.pieces(o);
    const std::size_t before = pieces_.size();
    for (const RotationPiece& p : ps)
      if (p.t1 >= t0 && p.t0 <= t1) pieces_.push_back(p);
    if (pieces_.size() == before) pieces_.push_back(source.piece_at(o, t0));  // [t0, t1] outside [0, horizon]
    first_.push_back(static_cast<std::uint32_t>(pieces_.size()));
  }
}

double Rotations::max_omega(std::size_t body, double u0, double u1) const {
  double m = 0.0;
  for (const RotationPiece& p : pieces(body))
    if (p.t1 >= u0 && p.t0 <= u1) m = std::max(m, p.max_rate());
  return m;
}

}  // namespace ccd
