#include <ccd/queries/sphere_box_distance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

constexpr double kU = 0.5 * std::numeric_limits<double>::epsilon();

// Whether the computed s = a - b is exact (Knuth's TwoSum error of a + (-b) is zero).
bool exact_difference(double a, double b, double s) {
  const double bb = s - a;
  return (a - (s - bb)) + (-b - bb) == 0.0;
}

// Whether the computed s = a + b is exact.
bool exact_sum(double a, double b, double s) { return exact_difference(a, -b, s); }

// R is a signed permutation: every entry -1, 0 or 1, one non-zero per row and column.
bool signed_permutation(const Eigen::Matrix3d& R) {
  for (int i = 0; i < 3; ++i) {
    int row = 0, col = 0;
    for (int j = 0; j < 3; ++j) {
      const double x = R(i, j), y = R(j, i);
      if (x != 0.0 && std::fabs(x) != 1.0) return false;
      row += x != 0.0;
      col += y != 0.0;
    }
    if (row != 1 || col != 1) return false;
  }
  return true;
}

// The point-box signed distance g of q (see the header) and whether it is exact, given
// that q is.
double point_box(const Vec3& q, const Vec3& h, bool& exact) {
  Vec3 e;
  for (int i = 0; i < 3; ++i) {
    e[i] = std::fabs(q[i]) - h[i];
    exact = exact && exact_difference(std::fabs(q[i]), h[i], e[i]);
  }
  if (e.maxCoeff() <= 0.0) return e.maxCoeff();
  // Outside one face's slab only: the distance is that excess itself, no root.
  if ((e.array() > 0.0).count() == 1) return e.maxCoeff();
  double s = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double x = std::max(e[i], 0.0);
    const double x2 = x * x;
    exact = exact && std::fma(x, x, -x2) == 0.0;
    const double t = s + x2;
    exact = exact && exact_sum(s, x2, t);
    s = t;
  }
  const double g = std::sqrt(s);
  exact = exact && std::fma(g, g, -s) == 0.0;
  return g;
}

}  // namespace

ConvexDistance sphere_box_distance(const Vec3& centre, double radius, const ProxyPose& box, const Vec3& half_extents) {
  const Eigen::Matrix3d& R = box.rotation;
  Vec3 d;
  bool exact = signed_permutation(R);
  for (int i = 0; i < 3; ++i) {
    d[i] = centre[i] - box.centre[i];
    exact = exact && exact_difference(centre[i], box.centre[i], d[i]);
  }
  // A signed permutation moves the components exactly; otherwise the allowance holds.
  const Vec3 q = R.transpose() * d;
  const double g = point_box(q, half_extents, exact);
  const double f = g - radius;
  exact = exact && exact_difference(g, radius, f);
  ConvexDistance out;
  double allowance = 0.0;
  if (!exact) {
    const double defect = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
    const double reach = d.norm() + half_extents.norm();
    allowance = (64.0 * kU * (reach + radius) + (defect + 32.0 * kU) * reach) * (1.0 + 8.0 * kU);
  }
  out.lower = f - allowance;
  out.upper = f + allowance;
  if (!std::isfinite(out.lower) || !std::isfinite(out.upper)) return out;  // Failed
  out.status = out.lower > 0.0    ? ConvexDistance::Status::Separated
               : out.upper < 0.0 ? ConvexDistance::Status::Overlapping
                                 : ConvexDistance::Status::Uncertain;
  out.iterations = 1;
  return out;
}

}  // namespace ccd
