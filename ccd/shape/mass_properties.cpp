#include <ccd/shape/mass_properties.hpp>

#include <ccd/shape/convex_hull.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace ccd {
namespace {

using Mat3 = Eigen::Matrix3d;

MassProperties from_diagonal(double volume, double density, const Vec3& per_mass) {
  MassProperties m;
  m.volume = volume;
  m.mass = density * volume;
  m.inertia = (m.mass * per_mass).asDiagonal();
  return m;
}

MassProperties hull_mass_properties(const std::vector<Vec3>& pts, double density) {
  Vec3 inner = Vec3::Zero();
  for (const Vec3& p : pts) inner += p;
  inner /= static_cast<double>(pts.size());
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // integral of x x^T, about `inner`
  for (const auto& t : convex_hull_triangles(pts)) {
    const Vec3 a = t[0] - inner, b = t[1] - inner, c = t[2] - inner;
    const double v = a.dot(b.cross(c)) / 6.0;
    const Vec3 sum = a + b + c;
    volume += v;
    first += v * sum / 4.0;
    second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  MassProperties m;
  m.volume = volume;
  m.mass = density * volume;
  const Vec3 c = first / volume;  // relative to `inner`
  m.centre = inner + c;
  const Mat3 cov = density * (second - volume * c * c.transpose());
  m.inertia = cov.trace() * Mat3::Identity() - cov;
  return m;
}

}  // namespace

MassProperties sphere_mass_properties(double r, double density) {
  return from_diagonal(4.0 / 3.0 * std::numbers::pi * r * r * r, density, Vec3::Constant(0.4 * r * r));
}

MassProperties mass_properties(const Shape& s, double density) {
  switch (s.kind) {
    case ShapeKind::Sphere: return sphere_mass_properties(s.radius, density);
    case ShapeKind::Box: {
      const Vec3 h = s.half_extents;
      const Vec3 h2 = h.cwiseProduct(h);
      return from_diagonal(8.0 * h.prod(), density, Vec3(h2.y() + h2.z(), h2.x() + h2.z(), h2.x() + h2.y()) / 3.0);
    }
    case ShapeKind::Capsule: {
      const double r = s.radius, h = s.half_length, pi = std::numbers::pi;
      const double vc = pi * r * r * 2.0 * h, vs = 4.0 / 3.0 * pi * r * r * r;
      MassProperties m;
      m.volume = vc + vs;
      m.mass = density * m.volume;
      const double mc = density * vc, ms = density * vs;
      const double axial = mc * r * r / 2.0 + ms * 0.4 * r * r;
      const double across = mc * (r * r / 4.0 + h * h / 3.0) + ms * (0.4 * r * r + h * h + 0.75 * h * r);
      m.inertia = Vec3(axial, across, across).asDiagonal();
      return m;
    }
    case ShapeKind::Hull: return hull_mass_properties(s.points, density);
  }
  return {};
}

PrincipalInertia principal_inertia(const Mat3& inertia) {
  PrincipalInertia p;
  const bool diagonal = inertia(0, 1) == 0.0 && inertia(0, 2) == 0.0 && inertia(1, 2) == 0.0 &&
                        inertia(1, 0) == 0.0 && inertia(2, 0) == 0.0 && inertia(2, 1) == 0.0;
  if (diagonal) {
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return inertia(a, a) < inertia(b, b); });
    for (int k = 0; k < 3; ++k) {
      p.moments[k] = inertia(order[k], order[k]);
      p.axes.col(k) = Vec3::Unit(order[k]);
    }
  } else {
    const Eigen::SelfAdjointEigenSolver<Mat3> es(0.5 * (inertia + inertia.transpose()));
    p.moments = es.eigenvalues();
    p.axes = es.eigenvectors();
  }
  if (p.axes.determinant() < 0.0) p.axes.col(2) = -p.axes.col(2);
  return p;
}

}  // namespace ccd
