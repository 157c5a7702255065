#pragma once
// Torque-free rotation of a rigid body in closed form (Euler-Poinsot; docs/rigid_bodies.md,
// "Free spin").
//
// The world angular momentum L is constant; the angular velocity is
// omega(t) = R(t) I^-1 R(t)^T L, I the inertia tensor in the body frame. In the principal
// frame, ordered so that the pole axis 3 is the one the body circles (the axis of largest
// moment when L^2 >= 2 E I_2, else that of the smallest), the body-frame momentum
// M = R^T L is
//     M_1 = A_1 cn(tau), M_2 = A_2 sn(tau), M_3 = s A_3 dn(tau),   tau = tau_0 + w (t - t0),
// Jacobi elliptic functions of modulus k^2 = I_3 (I_2 - I_1) A_1^2 / (I_1 (I_3 - I_2) A_3^2)
// with w^2 = (I_3 - I_2)(I_3 - I_1) A_3^2 / (I_1 I_2 I_3^2), and the orientation is
// R(t) = R_0 G^T Rz(phi(t)) B(M(t)) (principal frame), B(M) = Rx(theta) Rz(psi) the rotation
// whose third row is M / |L|, and
//     phi(t) = |L| (t - t0) / I_3 + |L| (I_3 - I_1) / (I_1 I_3 w) (P(tau) - P(tau_0)),
//     P(tau) = integral_0^tau du / (1 + n sn^2 u) = Pi(n; am tau | k), n = I_3 (I_2 - I_1) / (I_1 (I_3 - I_2)),
// the elliptic integral of the third kind. GSL evaluates sn, cn, dn (gsl_sf_elljac_e, after
// reducing tau by the half period 2K), F and Pi (gsl_sf_ellint_F, gsl_sf_ellint_P, their
// quasi-periodic extension past pi / 2 added here). A spin about a principal axis (M in one
// eigenspace of I) is a constant angular velocity and evaluates exactly as a prescribed
// spin.
//
// Accuracy: the closed form is exact; its evaluation in doubles carries rounding that grows
// with the phase. `orientation_error(t)` is a stated bound on the angle (radians) between
// the evaluated and the exact orientation: 2^-36 (1 + |tau - tau_0| + |phi| + 1 / k'),
// k' = sqrt(1 - k^2) (the conditioning near the separatrix), checked against a long-double
// integration of the equations of motion (tests/ccd/motion/free_rotation_test.cpp).
#include <ccd/geometry/vec3.hpp>

#include <Eigen/Geometry>

namespace ccd {

class FreeRotation {
 public:
  /// `moments` (> 0, any order) and `axes` (columns: the principal axes in the body frame,
  /// a proper rotation) describe the inertia; q0 (unit, body to world) and omega0 (world,
  /// rad/s) the state at t0.
  FreeRotation(const Vec3& moments, const Eigen::Matrix3d& axes, const Eigen::Quaterniond& q0, const Vec3& omega0,
               double t0);

  Eigen::Quaterniond orientation(double t) const;
  /// omega(t), world frame (rad/s).
  Vec3 angular_velocity(double t) const;
  /// The body-frame momentum R^T L at t in the working frame (the principal axes with the
  /// pole last; moments working_moments()).
  Vec3 working_momentum(double t) const;
  /// L in the world frame (units of the moments x rad/s).
  const Vec3& angular_momentum() const { return L_; }
  /// An upper bound on |omega(t)| for every t (rad/s).
  double max_omega() const { return max_omega_; }
  /// Bound on the orientation's evaluation error at t (radians); see the header.
  double orientation_error(double t) const;
  /// A spin about a principal axis: constant omega.
  bool constant() const { return constant_; }
  /// Period of the body-frame motion (s); +infinity for a constant spin or the separatrix.
  double period() const;
  /// Moments in the solution's working order (pole axis last) and k^2.
  const Vec3& working_moments() const { return I_; }
  double modulus_squared() const { return m_; }

 private:
  struct Phase {
    double sn = 0.0, cn = 1.0, dn = 1.0;  ///< of tau
    double amp = 0.0;                     ///< am(tau) reduced to [-pi/2, pi/2]
    double half_periods = 0.0;            ///< tau = reduced + 2K half_periods
    double tau = 0.0;
  };
  Phase phase(double t) const;
  /// P(tau) = integral_0^tau du / (1 + n sn^2 u).
  double third_kind(const Phase& p) const;
  Vec3 momentum(const Phase& p) const;
  /// Working frame to world at t.
  Eigen::Matrix3d working_rotation(double t, Vec3* momentum_out = nullptr) const;

  double t0_;
  Eigen::Quaterniond q0_;
  Vec3 omega0_;
  Vec3 L_;
  bool constant_ = false;
  double max_omega_ = 0.0;
  // Non-constant motion, in the working frame (x_work = W x_principal_sorted, pole last).
  Vec3 I_{Vec3::Ones()};
  Eigen::Matrix3d to_body_{Eigen::Matrix3d::Identity()};  ///< working frame to body frame
  Eigen::Matrix3d G_{Eigen::Matrix3d::Identity()};        ///< R_0 H B_0^T (see the .cpp)
  double A1_ = 0.0, A2_ = 0.0, A3_ = 0.0, s1_ = 1.0, s3_ = 1.0, I_min_ = 1.0;
  double m_ = 0.0, k_ = 0.0, K_ = 0.0, Pc_ = 0.0, n_ = 0.0, w_ = 0.0, tau0_ = 0.0, P0_ = 0.0, Lnorm_ = 0.0, C_ = 0.0;
};

}  // namespace ccd
