#include <ccd/motion/free_rotation.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_mode.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace ccd {
namespace {

using Mat3 = Eigen::Matrix3d;
constexpr double kPi = std::numbers::pi;

// GSL's special functions with the error handler off for the call (a domain error is
// reported through the status, which is checked by the callers' finite results).
struct GslQuiet {
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  ~GslQuiet() { gsl_set_error_handler(old); }
};

double ellint_F(double phi, double k) {
  gsl_sf_result r;
  gsl_sf_ellint_F_e(phi, k, GSL_PREC_DOUBLE, &r);
  return r.val;
}
// GSL's third kind: integral_0^phi dt / ((1 + n sin^2 t) sqrt(1 - k^2 sin^2 t)).
double ellint_P(double phi, double k, double n) {
  gsl_sf_result r;
  gsl_sf_ellint_P_e(phi, k, n, GSL_PREC_DOUBLE, &r);
  return r.val;
}

// The rotation whose third row is M / |M| (M1, M2 not both 0): Rx(theta) Rz(psi).
Mat3 pole_frame(const Vec3& M) {
  const double rho = std::hypot(M.x(), M.y());
  const double len = std::hypot(rho, M.z());
  const double st = rho / len, ct = M.z() / len, sp = M.x() / rho, cp = M.y() / rho;
  Mat3 rx, rz;
  rx << 1, 0, 0, 0, ct, -st, 0, st, ct;
  rz << cp, -sp, 0, sp, cp, 0, 0, 0, 1;
  return rx * rz;
}

Mat3 rot_z(double a) {
  Mat3 r;
  const double c = std::cos(a), s = std::sin(a);
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

}  // namespace

FreeRotation::FreeRotation(const Vec3& moments, const Mat3& axes, const Eigen::Quaterniond& q0, const Vec3& omega0,
                           double t0)
    : t0_(t0), q0_(q0), omega0_(omega0) {
  // Principal frame, moments ascending, a proper rotation.
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return moments[a] < moments[b]; });
  Mat3 S;
  Vec3 Ip;
  for (int k = 0; k < 3; ++k) {
    S.col(k) = axes.col(order[k]);
    Ip[k] = moments[order[k]];
  }
  if (S.determinant() < 0.0) S.col(2) = -S.col(2);
  const Mat3 R0 = q0.toRotationMatrix();
  const Vec3 M = Ip.cwiseProduct((R0 * S).transpose() * omega0);
  L_ = R0 * (S * M);
  I_min_ = Ip[0];
  const double g3 = M[0] * M[0] * ((Ip[2] - Ip[0]) / Ip[0]) + M[1] * M[1] * ((Ip[2] - Ip[1]) / Ip[1]);
  const double g1 = M[1] * M[1] * ((Ip[1] - Ip[0]) / Ip[1]) + M[2] * M[2] * ((Ip[2] - Ip[0]) / Ip[2]);
  if (g3 == 0.0 || g1 == 0.0 || (M[0] == 0.0 && M[2] == 0.0)) {
    // M in one eigenspace of I: omega = I^-1 M is parallel to M, a constant spin.
    constant_ = true;
    max_omega_ = omega0.norm() * (1.0 + 8.0 * kEps);
    return;
  }
  // Pole axis: 3 when L^2 >= 2 E I_2, else 1 (the frame (e3, e2, -e1), moments reversed).
  const double s = M[2] * M[2] * ((Ip[2] - Ip[1]) / Ip[2]) - M[0] * M[0] * ((Ip[1] - Ip[0]) / Ip[0]);
  Mat3 W = Mat3::Identity();  // x_working = W x_principal
  if (s < 0.0) W << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  I_ = s < 0.0 ? Vec3(Ip[2], Ip[1], Ip[0]) : Ip;
  const Vec3 Mw = W * M;
  to_body_ = S * W.transpose();
  const double I1 = I_[0], I2 = I_[1], I3 = I_[2];
  const double M1 = Mw[0], M2 = Mw[1], M3 = Mw[2];
  // Amplitudes, each a sum of non-negative terms (the ratios are >= 0 in either order).
  A1_ = std::sqrt(M1 * M1 + M2 * M2 * (I1 * (I3 - I2)) / (I2 * (I3 - I1)));
  A2_ = std::sqrt(M1 * M1 * (I2 * (I3 - I1)) / (I1 * (I3 - I2)) + M2 * M2);
  A3_ = std::sqrt(M2 * M2 * (I3 * (I2 - I1)) / (I2 * (I3 - I1)) + M3 * M3);
  Lnorm_ = M.norm();
  m_ = std::clamp((I3 * (I2 - I1) * A1_ * A1_) / (I1 * (I3 - I2) * A3_ * A3_), 0.0, 1.0);
  k_ = std::sqrt(m_);
  n_ = I3 * (I2 - I1) / (I1 * (I3 - I2));
  s3_ = M3 < 0.0 ? -1.0 : 1.0;
  // On the separatrix (k = 1) cn = sech > 0: the sign of M1 is a constant of the motion.
  s1_ = m_ == 1.0 && M1 < 0.0 ? -1.0 : 1.0;
  const double sigma = s1_ * s3_ * (I3 > I1 ? 1.0 : -1.0);
  w_ = sigma * std::sqrt(((I3 - I2) * (I3 - I1)) / (I1 * I2)) * (A3_ / std::fabs(I3));
  {
    const GslQuiet quiet;
    K_ = m_ < 1.0 ? gsl_sf_ellint_Kcomp(k_, GSL_PREC_DOUBLE) : std::numeric_limits<double>::infinity();
    Pc_ = m_ < 1.0 ? ellint_P(0.5 * kPi, k_, n_) : std::numeric_limits<double>::infinity();
    if (m_ < 1.0) {
      // tau_0 from cn = M1 / (s1 A1), sn = M2 / A2: tau_0 = F(am) with F extended by
      // F(phi + j pi) = F(phi) + 2 j K.
      const double amp = std::atan2(M2 / A2_, (s1_ * M1) / A1_);
      const double j = std::round(amp / kPi);
      const double red = amp - j * kPi;
      tau0_ = ellint_F(red, k_) + (j != 0.0 ? 2.0 * j * K_ : 0.0);
    } else {
      // The separatrix (k^2 rounds to 1): sn = tanh, cn = dn = sech, sinh tau_0 = sn / cn.
      tau0_ = std::asinh((M2 / A2_) / ((s1_ * M1) / A1_));
      if (!std::isfinite(tau0_)) {  // at the intermediate axis's equilibrium to rounding
        constant_ = true;
        max_omega_ = omega0.norm() * (1.0 + 8.0 * kEps);
        return;
      }
    }
  }
  C_ = Lnorm_ * (I3 - I1) / (I1 * I3 * w_);
  const Phase p0 = phase(t0);
  P0_ = third_kind(p0);
  G_ = R0 * to_body_ * pole_frame(momentum(p0)).transpose();
  const double bound = std::sqrt(std::pow(A1_ / I1, 2) + std::pow(A2_ / I2, 2) + std::pow(A3_ / I3, 2));
  max_omega_ = std::min(bound, Lnorm_ / I_min_) * (1.0 + 64.0 * kEps);
}

FreeRotation::Phase FreeRotation::phase(double t) const {
  const GslQuiet quiet;
  Phase p;
  const double tau = tau0_ + w_ * (t - t0_);
  p.tau = tau;
  if (!(m_ < 1.0)) {
    p.sn = std::tanh(tau);
    p.cn = p.dn = 1.0 / std::cosh(tau);
    p.amp = std::atan2(p.sn, p.cn);
    return p;
  }
  p.half_periods = std::round(tau / (2.0 * K_));
  const double u = tau - 2.0 * K_ * p.half_periods;
  gsl_sf_elljac_e(u, m_, &p.sn, &p.cn, &p.dn);
  p.amp = std::atan2(p.sn, p.cn);
  if (std::fmod(std::fabs(p.half_periods), 2.0) == 1.0) {
    p.sn = -p.sn;
    p.cn = -p.cn;
  }
  return p;
}

double FreeRotation::third_kind(const Phase& p) const {
  if (!(m_ < 1.0)) {
    // k = 1: integral_0^tau du / (1 + n tanh^2 u) = (tau + sqrt(n) atan(sqrt(n) tanh tau)) / (1 + n).
    const double r = std::sqrt(n_);
    return (p.tau + r * std::atan(r * std::tanh(p.tau))) / (1.0 + n_);
  }
  const GslQuiet quiet;
  return ellint_P(p.amp, k_, n_) + (p.half_periods != 0.0 ? 2.0 * p.half_periods * Pc_ : 0.0);
}

Vec3 FreeRotation::momentum(const Phase& p) const { return {s1_ * A1_ * p.cn, A2_ * p.sn, s3_ * A3_ * p.dn}; }

Mat3 FreeRotation::working_rotation(double t, Vec3* momentum_out) const {
  const Phase p = phase(t);
  const double P = third_kind(p);
  const double phi = Lnorm_ * (t - t0_) / I_[2] + C_ * (P - P0_);
  const Vec3 M = momentum(p);
  if (momentum_out) *momentum_out = M;
  return G_ * rot_z(phi) * pole_frame(M);
}

Eigen::Quaterniond FreeRotation::orientation(double t) const {
  if (constant_) {  // RotationPiece::orientation, term for term
    const double w = omega0_.norm();
    if (w == 0.0) return q0_;
    const double half = 0.5 * w * (t - t0_);
    const Vec3 axis = omega0_ / w;
    const Eigen::Quaterniond step(std::cos(half), std::sin(half) * axis.x(), std::sin(half) * axis.y(),
                                  std::sin(half) * axis.z());
    return (step * q0_).normalized();
  }
  Eigen::Quaterniond q(Mat3(working_rotation(t) * to_body_.transpose()));
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return q.normalized();
}

Vec3 FreeRotation::working_momentum(double t) const {
  if (constant_) return L_;  // not used for a constant spin: L in the world frame
  return momentum(phase(t));
}

Vec3 FreeRotation::angular_velocity(double t) const {
  if (constant_) return omega0_;
  Vec3 M;
  const Mat3 R = working_rotation(t, &M);
  return R * M.cwiseQuotient(I_);
}

double FreeRotation::orientation_error(double t) const {
  if (constant_) return 0.0;
  const double kp = std::sqrt(std::max(1.0 - m_, kEps));
  return std::ldexp(1.0 + (std::fabs(w_) + Lnorm_ / I_min_) * std::fabs(t - t0_) + 1.0 / kp, -36);
}

double FreeRotation::period() const {
  if (constant_ || !(m_ < 1.0)) return std::numeric_limits<double>::infinity();
  return 4.0 * K_ / std::fabs(w_);
}

}  // namespace ccd
