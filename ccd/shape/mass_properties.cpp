#include <ccd/shape/mass_properties.hpp>

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

// The faces of the convex hull of `pts` as triangles (outward by the right-hand rule).
std::vector<std::array<Vec3, 3>> hull_triangles(const std::vector<Vec3>& pts) {
  double scale = 0.0;
  for (const Vec3& p : pts) scale = std::max(scale, p.norm());
  const double tol = 1e-9 * scale;
  std::vector<std::array<Vec3, 3>> out;
  std::vector<std::pair<Vec3, double>> planes;  // unit normal, offset
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        Vec3 nrm = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
        const double len = nrm.norm();
        if (!(len > tol * scale)) continue;
        nrm /= len;
        double lo = 0.0, hi = 0.0;
        for (const Vec3& p : pts) {
          const double s = nrm.dot(p - pts[i]);
          lo = std::min(lo, s);
          hi = std::max(hi, s);
        }
        if (lo < -tol && hi > tol) continue;  // points on both sides: not a face
        if (hi > tol) nrm = -nrm;               // outward: every point behind the plane
        const double off = nrm.dot(pts[i]);
        bool seen = false;
        for (const auto& [m, o] : planes) seen = seen || ((m - nrm).norm() < 1e-9 && std::fabs(o - off) <= tol);
        if (seen) continue;
        planes.push_back({nrm, off});
        // The face: the points on the plane, their convex polygon in the plane (monotone
        // chain), fanned from its first corner.
        const Vec3 u = (std::fabs(nrm.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(nrm).normalized();
        const Vec3 w = nrm.cross(u);
        std::vector<std::pair<Eigen::Vector2d, Vec3>> face;
        for (const Vec3& p : pts)
          if (std::fabs(nrm.dot(p) - off) <= tol) face.push_back({{u.dot(p), w.dot(p)}, p});
        std::sort(face.begin(), face.end(), [](const auto& a, const auto& b) {
          return a.first.x() < b.first.x() || (a.first.x() == b.first.x() && a.first.y() < b.first.y());
        });
        auto cross2 = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
          return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
        };
        std::vector<std::size_t> ring;  // counter-clockwise in (u, w): outward along nrm
        for (int pass = 0; pass < 2; ++pass) {
          const std::size_t base = ring.size();
          for (std::size_t q = 0; q < face.size(); ++q) {
            const std::size_t idx = pass == 0 ? q : face.size() - 1 - q;
            while (ring.size() >= base + 2 &&
                   cross2(face[ring[ring.size() - 2]].first, face[ring.back()].first, face[idx].first) <= 0.0)
              ring.pop_back();
            ring.push_back(idx);
          }
          ring.pop_back();
        }
        for (std::size_t q = 1; q + 1 < ring.size(); ++q)
          out.push_back({face[ring[0]].second, face[ring[q]].second, face[ring[q + 1]].second});
      }
  return out;
}

MassProperties hull_mass_properties(const std::vector<Vec3>& pts, double density) {
  Vec3 inner = Vec3::Zero();
  for (const Vec3& p : pts) inner += p;
  inner /= static_cast<double>(pts.size());
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // integral of x x^T, about `inner`
  for (const auto& t : hull_triangles(pts)) {
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
