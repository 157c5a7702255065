#pragma once
// The cloth motion source: a mass-spring cloth integrated with implicit Euler (Baraff and
// Witkin 1998), one linear solve per step with Eigen's sparse conjugate gradient.
//
// Per step h, with forces f(x, v) (damped Hooke springs, gravity and air drag):
//   (M - h df/dv - h^2 df/dx) dv = h (f + h df/dx v),  v += dv,  x += h v.
// The stiffness Jacobian of a spring drops its negative (compressed) part so that the
// matrix stays symmetric positive definite. Pinned particles keep their place; spun
// particles follow their rigid rotation exactly (their dv is prescribed, and their coupling
// terms move to the right-hand side).
//
// Obstacles: after each step a free particle closer than `thickness` to a sphere or to the
// floor is moved out to that distance, and the inward normal part of its velocity is
// removed (inelastic, no friction). Self-collisions are not resolved: the cloth is the
// motion whose self-contacts ccdlab measures. Between two integrator states each particle
// moves linearly (the standard CCD assumption).
#include <cloth/sim/cloth_mesh.hpp>
#include <cloth/sim/cloth_scene.hpp>

#include <vector>

namespace ccd::cloth {

class ClothSimulator {
 public:
  explicit ClothSimulator(const ClothScene& scene);
  /// Advances one step h. Throws std::runtime_error if the state stops being finite.
  void step();
  const std::vector<Vec3>& positions() const { return x_; }
  const std::vector<Vec3>& velocities() const { return v_; }
  const ClothMesh& mesh() const { return mesh_; }
  double time() const { return time_; }
  /// Conjugate-gradient iterations of the last step.
  int last_iterations() const { return iterations_; }

 private:
  Vec3 spun_position(std::uint32_t p, double t) const;
  ClothScene scene_;
  ClothMesh mesh_;
  std::vector<Vec3> x0_, x_, v_;
  std::vector<char> fixed_;  // 0 free, 1 pinned, 2 spun
  double time_ = 0.0;
  int iterations_ = 0;
};

/// The particle positions at t = 0, h, 2h, ..., steps h (steps + 1 frames).
std::vector<std::vector<Vec3>> simulate_cloth(const ClothScene& scene);

}  // namespace ccd::cloth
