#include <bounds/oriented_box.hpp>
#include <bounds/oriented_trapezoid.hpp>

#include <cmath>
#include <limits>

namespace ccd {

bool oriented_boxes_overlap(const OrientedBox& a, const OrientedBox& b) {
  const Eigen::Matrix3d R = a.axes.transpose() * b.axes;  // R(i, j) = a_i . b_j
  const Eigen::Matrix3d Q = R.cwiseAbs().array() + kSatParallelEpsilon;
  const Vec3 T = b.centre - a.centre;
  const Vec3 ta = a.axes.transpose() * T;  // T in a's frame
  const Vec3& ha = a.half;
  const Vec3& hb = b.half;
  const double slack = 16.0 * std::numeric_limits<double>::epsilon() * (T.cwiseAbs().sum() + ha.sum() + hb.sum());
  for (int i = 0; i < 3; ++i)  // a's face normals
    if (std::abs(ta[i]) > ha[i] + Q.row(i).dot(hb) + slack) return false;
  for (int j = 0; j < 3; ++j)  // b's face normals: T . b_j = ta . R(:, j)
    if (std::abs(ta.dot(R.col(j))) > Q.col(j).dot(ha) + hb[j] + slack) return false;
  for (int i = 0; i < 3; ++i) {  // a_i x b_j
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double p = ta[i2] * R(i1, j) - ta[i1] * R(i2, j);
      const double ra = ha[i1] * Q(i2, j) + ha[i2] * Q(i1, j);
      const double rb = hb[j1] * Q(i, j2) + hb[j2] * Q(i, j1);
      if (std::abs(p) > ra + rb + slack) return false;
    }
  }
  return true;
}

}  // namespace ccd
