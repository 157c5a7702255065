#include <bounds/oriented_trapezoid.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace ccd {

Aabb OrientedTrapezoid::hull() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo = Vec3::Constant(inf), hi = Vec3::Constant(-inf);
  merge_oriented_hull(axes.cwiseAbs(), c0, c1, h0, h1, lo, hi);
  return {lo, hi};
}

SatFrames::SatFrames(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
    : a_axes(a), b_axes(b), r(a.transpose() * b) {
  abs_r = r.cwiseAbs().array() + kSatParallelEpsilon;
}

PairTest oriented_overlap(const SatFrames& f, double t0, double t1, const Vec3& ca0, const Vec3& ca1,
                                  const Vec3& ha0, const Vec3& ha1, const Vec3& cb0, const Vec3& cb1,
                                  const Vec3& hb0, const Vec3& hb1) {
  const Vec3 T0 = cb0 - ca0;
  const Vec3 T1 = cb1 - ca1;
  const Vec3 ta0 = f.a_axes.transpose() * T0;
  const Vec3 ta1 = f.a_axes.transpose() * T1;
  const Vec3 tb0 = f.b_axes.transpose() * T0;
  const Vec3 tb1 = f.b_axes.transpose() * T1;
  const double slack = 16.0 * kEps *
                       (T0.cwiseAbs().sum() + T1.cwiseAbs().sum() + ha0.sum() + ha1.sum() + hb0.sum() + hb1.sum());
  const Eigen::Matrix3d& R = f.r;
  const Eigen::Matrix3d& Q = f.abs_r;
  double u_lo = 0.0;
  double u_hi = 1.0;
  // |p| <= rad on [0, 1] with p, rad linear: rad - p >= 0 and rad + p >= 0.
  const auto axis = [&](double p0, double p1, double rad0, double rad1) {
    rad0 += slack;
    rad1 += slack;
    detail::clip_nonnegative(rad0 - p0, rad1 - p1, u_lo, u_hi);
    detail::clip_nonnegative(rad0 + p0, rad1 + p1, u_lo, u_hi);
    return u_lo <= u_hi;
  };
  for (int i = 0; i < 3; ++i) {  // a's face normals
    if (!axis(ta0[i], ta1[i], ha0[i] + Q.row(i).dot(hb0), ha1[i] + Q.row(i).dot(hb1))) return {};
  }
  for (int j = 0; j < 3; ++j) {  // b's face normals
    if (!axis(tb0[j], tb1[j], Q.col(j).dot(ha0) + hb0[j], Q.col(j).dot(ha1) + hb1[j])) return {};
  }
  for (int i = 0; i < 3; ++i) {  // a_i x b_j
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double p0 = ta0[i2] * R(i1, j) - ta0[i1] * R(i2, j);
      const double p1 = ta1[i2] * R(i1, j) - ta1[i1] * R(i2, j);
      const double ra0 = ha0[i1] * Q(i2, j) + ha0[i2] * Q(i1, j);
      const double ra1 = ha1[i1] * Q(i2, j) + ha1[i2] * Q(i1, j);
      const double rb0 = hb0[j1] * Q(i, j2) + hb0[j2] * Q(i, j1);
      const double rb1 = hb1[j1] * Q(i, j2) + hb1[j2] * Q(i, j1);
      if (!axis(p0, p1, ra0 + rb0, ra1 + rb1)) return {};
    }
  }
  u_lo = std::max(u_lo, 0.0);
  return {PairTest::Status::Possible, t0 + u_lo * (t1 - t0)};
}

Eigen::Matrix3d velocity_frame(const Vec3& v) {
  const double n2 = v.squaredNorm();
  if (!(n2 >= 1e-200)) return Eigen::Matrix3d::Identity();
  const Vec3 x = v / std::sqrt(n2);
  int k = 0;  // the coordinate axis least aligned with v (first on ties)
  for (int i = 1; i < 3; ++i)
    if (std::abs(x[i]) < std::abs(x[k])) k = i;
  Vec3 y = -x[k] * x;
  y[k] += 1.0;
  y.normalize();
  const Vec3 z = x.cross(y);
  Eigen::Matrix3d m;
  m.col(0) = x;
  m.col(1) = y;
  m.col(2) = z;
  return m;
}

}  // namespace ccd

