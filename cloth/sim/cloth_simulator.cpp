#include "cloth_simulator.hpp"

#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <cmath>
#include <stdexcept>

namespace ccd::cloth {

namespace {
using Mat3 = Eigen::Matrix3d;
constexpr double kCgTolerance = 1e-10;
constexpr int kCgMaxIterations = 1000;
}  // namespace

ClothSimulator::ClothSimulator(const ClothScene& scene)
    : scene_(scene), mesh_(make_grid_mesh(scene)), x0_(initial_positions(scene)), x_(x0_),
      v_(x0_.size(), Vec3::Zero()), fixed_(x0_.size(), 0) {
  for (std::uint32_t p : scene_.pinned) fixed_[p] = 1;
  if (scene_.spin)
    for (std::uint32_t p : scene_.spin->particles) {
      fixed_[p] = 2;
      v_[p] = scene_.spin->rate * scene_.spin->axis.cross(x_[p] - scene_.spin->center);
    }
}

Vec3 ClothSimulator::spun_position(std::uint32_t p, double t) const {
  const Spin& s = *scene_.spin;
  return s.center + Eigen::AngleAxisd(s.rate * t, s.axis) * (x0_[p] - s.center);
}

void ClothSimulator::step() {
  const double h = scene_.step, m = scene_.particle_mass;
  const std::size_t n = x_.size();
  // Prescribed velocity changes of pinned and spun particles.
  std::vector<Vec3> dv_fixed(n, Vec3::Zero());
  for (std::size_t p = 0; p < n; ++p) {
    if (fixed_[p] == 1) dv_fixed[p] = -v_[p];
    if (fixed_[p] == 2)
      dv_fixed[p] = (spun_position(static_cast<std::uint32_t>(p), time_ + h) - x_[p]) / h - v_[p];
  }
  Eigen::VectorXd b(3 * n);
  const double drag = scene_.air_damping;  // f = -drag v, df/dv = -drag I
  for (std::size_t p = 0; p < n; ++p)
    b.segment<3>(static_cast<Eigen::Index>(3 * p)) = h * (m * scene_.gravity - drag * v_[p]);
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(36 * mesh_.springs.size() + 3 * n);
  for (std::size_t p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) trip.emplace_back(static_cast<int>(3 * p) + k, static_cast<int>(3 * p) + k, fixed_[p] ? 1.0 : m + h * drag);
  auto add_block = [&](std::uint32_t i, std::uint32_t j, const Mat3& block) {
    // A_ij += block; couplings to prescribed particles move to the right-hand side.
    if (fixed_[i]) return;
    if (fixed_[j]) {
      b.segment<3>(3 * static_cast<Eigen::Index>(i)) -= block * dv_fixed[j];
      return;
    }
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) trip.emplace_back(static_cast<int>(3 * i) + r, static_cast<int>(3 * j) + c, block(r, c));
  };
  for (const Spring& s : mesh_.springs) {
    const SpringParams& prm = s.kind == SpringKind::Structural ? scene_.structural
                              : s.kind == SpringKind::Shear    ? scene_.shear
                                                               : scene_.bend;
    const Vec3 d = x_[s.b] - x_[s.a];
    const double len = d.norm();
    if (len <= 0.0) continue;  // coincident particles: no direction, no force
    const Vec3 u = d / len;
    const Vec3 dvel = v_[s.b] - v_[s.a];
    const Vec3 f = (prm.stiffness * (len - s.rest) + prm.damping * dvel.dot(u)) * u;  // on a; -f on b
    const Mat3 uu = u * u.transpose();
    // df_a/dx_a = -K, K = k (u u^T + max(0, 1 - rest/len) (I - u u^T)); df_a/dv_a = -c u u^T.
    const Mat3 K = prm.stiffness * (uu + std::max(0.0, 1.0 - s.rest / len) * (Mat3::Identity() - uu));
    const Mat3 D = prm.damping * uu;
    const Mat3 block = h * D + h * h * K;  // A_aa, A_bb += block; A_ab, A_ba -= block
    // b += h (f + h df/dx v): (df/dx v)_a = K (v_b - v_a), (df/dx v)_b = -K (v_b - v_a).
    const Vec3 kv = h * h * (K * dvel);
    if (!fixed_[s.a]) b.segment<3>(3 * static_cast<Eigen::Index>(s.a)) += h * f + kv;
    if (!fixed_[s.b]) b.segment<3>(3 * static_cast<Eigen::Index>(s.b)) -= h * f + kv;
    add_block(s.a, s.a, block);
    add_block(s.b, s.b, block);
    add_block(s.a, s.b, -block);
    add_block(s.b, s.a, -block);
  }
  for (std::size_t p = 0; p < n; ++p)
    if (fixed_[p]) b.segment<3>(static_cast<Eigen::Index>(3 * p)) = dv_fixed[p];
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(3 * n), static_cast<Eigen::Index>(3 * n));
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kCgTolerance);
  cg.setMaxIterations(kCgMaxIterations);
  cg.compute(A);
  const Eigen::VectorXd dv = cg.solve(b);
  iterations_ = static_cast<int>(cg.iterations());
  if (!dv.allFinite()) throw std::runtime_error("cloth: the implicit step did not give finite velocities");
  time_ += h;
  for (std::size_t p = 0; p < n; ++p) {
    v_[p] += dv.segment<3>(static_cast<Eigen::Index>(3 * p));
    if (fixed_[p] == 1) {
      v_[p] = Vec3::Zero();
      continue;
    }
    if (fixed_[p] == 2) {
      x_[p] = spun_position(static_cast<std::uint32_t>(p), time_);
      continue;
    }
    x_[p] += h * v_[p];
    for (const SphereObstacle& o : scene_.spheres) {
      const Vec3 d = x_[p] - o.center;
      const double r = o.radius + scene_.thickness, len = d.norm();
      if (len < r && len > 0.0) {
        const Vec3 nrm = d / len;
        x_[p] = o.center + r * nrm;
        v_[p] -= std::min(0.0, v_[p].dot(nrm)) * nrm;
      }
    }
    if (scene_.floor && x_[p].y() < *scene_.floor + scene_.thickness) {
      x_[p].y() = *scene_.floor + scene_.thickness;
      v_[p].y() = std::max(0.0, v_[p].y());
    }
  }
}

std::vector<std::vector<Vec3>> simulate_cloth(const ClothScene& scene) {
  ClothSimulator sim(scene);
  std::vector<std::vector<Vec3>> frames{sim.positions()};
  for (int k = 0; k < scene.steps; ++k) {
    sim.step();
    frames.push_back(sim.positions());
  }
  return frames;
}

}  // namespace ccd::cloth
