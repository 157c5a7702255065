#include <ccd/queries/sphere_polygon.hpp>

#include <ccd/queries/polynomial_roots.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace ccd {
namespace {

// A vector quadratic w(s) = w0 + w1 s + w2 s^2 / 2 (w2 the acceleration).
struct VecQuadratic {
  Vec3 w0, w1, w2;
};

// |w(s)|^2 - k.
Polynomial squared_norm_minus(const VecQuadratic& w, double k) {
  Polynomial p;
  p.c[4] = 0.25 * w.w2.squaredNorm();
  p.c[3] = w.w1.dot(w.w2);
  p.c[2] = w.w1.squaredNorm() + w.w0.dot(w.w2);
  p.c[1] = 2.0 * w.w0.dot(w.w1);
  p.c[0] = w.w0.squaredNorm() - k;
  return p;
}

// sign * (d . w(s)) + shift.
Polynomial linear_form(const Vec3& d, const VecQuadratic& w, double sign, double shift) {
  Polynomial p;
  p.c[2] = sign * 0.5 * d.dot(w.w2);
  p.c[1] = sign * d.dot(w.w1);
  p.c[0] = sign * d.dot(w.w0) + shift;
  return p;
}

// The sets of one feature are intersected into `acc` (sorted, disjoint, closed).
class Feature {
 public:
  Feature(double s0, double s1, std::vector<RootInterval>& acc, std::vector<RootInterval>& scratch)
      : s0_(s0), s1_(s1), acc_(acc), scratch_(scratch) {
    acc_.clear();
    acc_.push_back({s0, s1});
  }
  /// Intersects with {s : p(s) <= 0}; returns false once the feature's set is empty.
  bool require(const Polynomial& p) {
    if (acc_.empty()) return false;
    const SublevelSet set = polynomial_sublevel_set(p, s0_, s1_, 2.0 * polynomial_rounding_bound(p, s0_, s1_));
    scratch_.clear();
    for (const RootInterval& x : acc_)
      for (int k = 0; k < set.count; ++k) {
        const RootInterval& y = set.intervals[k];
        const double lo = std::max(x.lo, y.lo), hi = std::min(x.hi, y.hi);
        if (lo <= hi) scratch_.push_back({lo, hi});
      }
    acc_.swap(scratch_);
    return !acc_.empty();
  }

 private:
  double s0_, s1_;
  std::vector<RootInterval>& acc_;
  std::vector<RootInterval>& scratch_;
};

bool finite(const Vec3& x) { return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]); }

}  // namespace

void sphere_polygon_contacts(const Vec3& p, const Vec3& v, const Vec3& a, double t_ref, double r,
                             const StaticPolygon& poly, double u0, double u1, std::vector<ContactInterval>& out) {
  const std::size_t nv = poly.vertices.size();
  if (nv < 3 || !(u1 >= u0) || !(r >= 0.0) || !finite(p) || !finite(v) || !finite(a) || !std::isfinite(t_ref) ||
      !std::isfinite(u0) || !std::isfinite(u1) || !finite(poly.normal))
    return;
  const double s0 = u0 - t_ref, s1 = u1 - t_ref;

  // Quick rejection: the centre's path box, grown by r and a rounding margin, against the
  // polygon's box.
  {
    Vec3 lo, hi, plo = poly.vertices[0], phi = poly.vertices[0];
    for (const Vec3& x : poly.vertices) {
      plo = plo.cwiseMin(x);
      phi = phi.cwiseMax(x);
    }
    for (int k = 0; k < 3; ++k) {
      auto at = [&](double s) { return p[k] + v[k] * s + 0.5 * a[k] * s * s; };
      double l = std::min(at(s0), at(s1)), h = std::max(at(s0), at(s1));
      if (a[k] != 0.0) {
        const double sv = -v[k] / a[k];
        if (sv > s0 && sv < s1) {
          l = std::min(l, at(sv));
          h = std::max(h, at(sv));
        }
      }
      const double margin = r * (1.0 + 1e-9) +
                            1e-9 * (std::fabs(p[k]) + std::fabs(v[k]) * std::max(std::fabs(s0), std::fabs(s1)) +
                                    std::fabs(a[k]) * (s0 * s0 + s1 * s1) + std::fabs(plo[k]) + std::fabs(phi[k])) +
                            std::numeric_limits<double>::denorm_min();
      if (l - margin > phi[k] || h + margin < plo[k]) return;
    }
  }

  std::vector<RootInterval> all, acc, scratch;
  auto collect = [&] { all.insert(all.end(), acc.begin(), acc.end()); };
  const Vec3& n = poly.normal;
  const double r2 = r * r;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& x : poly.vertices) centroid += x;
  centroid /= static_cast<double>(nv);

  // Face: within r of the plane while projecting inside every edge.
  {
    const VecQuadratic w{p - poly.vertices[0], v, a};
    Feature f(s0, s1, acc, scratch);
    bool ok = f.require(linear_form(n, w, 1.0, -r)) && f.require(linear_form(n, w, -1.0, -r));
    for (std::size_t i = 0; ok && i < nv; ++i) {
      const Vec3& vi = poly.vertices[i];
      const Vec3 e = poly.vertices[(i + 1) % nv] - vi;
      Vec3 m = n.cross(e);
      if (m.isZero(0.0)) continue;
      if (m.dot(centroid - vi) < 0.0) m = -m;  // inward, whatever the winding
      ok = f.require(linear_form(m, VecQuadratic{p - vi, v, a}, -1.0, 0.0));
    }
    if (ok) collect();
  }
  // Edges (line distance within the slab) and vertices.
  for (std::size_t i = 0; i < nv; ++i) {
    const Vec3& vi = poly.vertices[i];
    const Vec3& vj = poly.vertices[(i + 1) % nv];
    const VecQuadratic wi{p - vi, v, a};
    {
      Feature f(s0, s1, acc, scratch);
      if (f.require(squared_norm_minus(wi, r2))) collect();
    }
    const Vec3 e = vj - vi;
    const double e2 = e.squaredNorm();
    if (!(e2 > 0.0)) continue;
    const VecQuadratic cross{e.cross(wi.w0), e.cross(v), e.cross(a)};
    Feature f(s0, s1, acc, scratch);
    if (f.require(squared_norm_minus(cross, r2 * e2)) && f.require(linear_form(e, wi, -1.0, 0.0)) &&
        f.require(linear_form(e, VecQuadratic{p - vj, v, a}, 1.0, 0.0)))
      collect();
  }
  if (all.empty()) return;

  std::sort(all.begin(), all.end(), [](const RootInterval& x, const RootInterval& y) { return x.lo < y.lo; });
  auto to_time = [&](double s) {
    if (s <= s0) return u0;
    if (s >= s1) return u1;
    return std::clamp(t_ref + s, u0, u1);
  };
  RootInterval cur = all[0];
  auto emit = [&](const RootInterval& x) { out.push_back({to_time(x.lo), to_time(x.hi)}); };
  for (std::size_t k = 1; k < all.size(); ++k) {
    if (all[k].lo <= cur.hi) {
      cur.hi = std::max(cur.hi, all[k].hi);
    } else {
      emit(cur);
      cur = all[k];
    }
  }
  emit(cur);
}

}  // namespace ccd
