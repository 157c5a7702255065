#include <ccd/queries/sphere_polygon.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <ccd/geometry/double_double.hpp>
#include <ccd/queries/certified_sublevel_set.hpp>
#include <ccd/queries/pair_motion.hpp>
#include <ccd/queries/polynomial_roots.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

constexpr double kU2 = kUnitRoundoff * kUnitRoundoff;
constexpr double kPad = 1.0 + 1e-6;

// b - a exactly (the difference of two doubles is a double-double).
DdVec3 exact_difference(const Vec3& b, const Vec3& a) {
  DdVec3 r;
  for (int k = 0; k < 3; ++k) r[k] = two_sum(b[k], -a[k]);
  return r;
}

DdVec3 cross(const DdVec3& a, const DdVec3& b) {
  DdVec3 r;
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
  return r;
}

double norm(const DdVec3& a) { return a.rounded().norm() * kPad; }
double max_abs(const DdVec3& a) { return a.rounded().cwiseAbs().maxCoeff() * kPad; }

// A polynomial h0 + h1 s + h2 s^2 squared, minus k.
Polynomial square_minus(double h0, double h1, double h2, double k) {
  Polynomial p;
  p.c[4] = h2 * h2;
  p.c[3] = 2.0 * h1 * h2;
  p.c[2] = h1 * h1 + 2.0 * h0 * h2;
  p.c[1] = 2.0 * h0 * h1;
  p.c[0] = h0 * h0 - k;
  return p;
}

// One condition g(t) <= 0 of a feature, a polynomial in the offset w(t) = c(t) - V of the
// centre from a vertex V (docs/truth.md, "Body against scenery"):
//   Linear:         sign (A . w)
//   SquaredLinear:  (A . w)^2 - K
//   SquaredNorm:    |w|^2 - K
//   SquaredCross:   |A x w|^2 - K
// A and K are double-doubles off their exact values by at most a_error (per coordinate)
// and k_error. value() evaluates g in double-double with a certified bound on its
// distance from the exact g; the model's data (the piece's exact state, the vertices,
// the radius) are exact.
class Condition {
 public:
  enum class Kind { Linear, SquaredLinear, SquaredNorm, SquaredCross };

  Condition(Kind kind, const Piece& q, const PieceLow& low, const Vec3& vertex, const DdVec3& A, double a_error,
            double sign, const Dd& K, double k_error)
      : kind_(kind), q_(&q), low_(&low), vertex_(vertex), A_(A), a_error_(a_error), sign_(sign), K_(K),
        k_error_(k_error), a_norm_(norm(A)), a_max_(max_abs(A)) {}

  ContactValue value(double t) const {
    const DdVec3 w = exact_position(*q_, *low_, t) - DdVec3(vertex_);
    const double wn = norm(w), wm = max_abs(w);
    const double ew = position_error(*q_, *low_, t) + 4.0 * kU2 * wm;
    const double K = K_.value();
    switch (kind_) {
      case Kind::Linear: {
        const Dd h = dot(A_, w);
        return {sign_ * h.value(), linear_error(wn, ew) * kPad};
      }
      case Kind::SquaredLinear: {
        const Dd h = dot(A_, w);
        const double eh = linear_error(wn, ew), hv = std::fabs(h.value()) * kPad;
        const double g = (h * h - K_).value();
        return {g, (2.0 * hv * eh + eh * eh + 16.0 * kU2 * (hv * hv + std::fabs(K)) + k_error_ +
                    4.0 * kU2 * std::fabs(g)) *
                       kPad};
      }
      case Kind::SquaredNorm: {
        const double g = (dot(w, w) - K_).value();
        const double ed = std::sqrt(3.0) * kPad * ew;
        return {g,
                (2.0 * wn * ed + ed * ed + 16.0 * kU2 * (wn * wn + std::fabs(K)) + k_error_ + 4.0 * kU2 * std::fabs(g)) *
                    kPad};
      }
      case Kind::SquaredCross: {
        const DdVec3 x = cross(A_, w);
        const double xn = norm(x);
        const double ex =
            std::sqrt(3.0) * kPad * (2.0 * a_max_ * ew + 2.0 * wm * a_error_ + 2.0 * ew * a_error_ + 16.0 * kU2 * a_norm_ * wn);
        const double g = (dot(x, x) - K_).value();
        return {g,
                (2.0 * xn * ex + ex * ex + 16.0 * kU2 * (xn * xn + std::fabs(K)) + k_error_ + 4.0 * kU2 * std::fabs(g)) *
                    kPad};
      }
    }
    return {};
  }

  double slope(double t) const {
    const DdVec3 w = exact_position(*q_, *low_, t) - DdVec3(vertex_);
    const DdVec3 wv = exact_velocity(*q_, *low_, t);
    switch (kind_) {
      case Kind::Linear: return sign_ * dot(A_, wv).value();
      case Kind::SquaredLinear: return 2.0 * (dot(A_, w) * dot(A_, wv)).value();
      case Kind::SquaredNorm: return 2.0 * dot(w, wv).value();
      case Kind::SquaredCross: return 2.0 * dot(cross(A_, w), cross(A_, wv)).value();
    }
    return 0.0;
  }

  double curvature_bound(double t) const {
    const Vec3 w = q_->position(t) - vertex_, wv = q_->velocity(t), wa = q_->a;
    const double an = a_norm_;
    double b = 0.0;
    switch (kind_) {
      case Kind::Linear: b = an * wa.norm(); break;
      case Kind::SquaredLinear: b = 2.0 * an * an * (wv.squaredNorm() + w.norm() * wa.norm()); break;
      case Kind::SquaredNorm: b = 2.0 * (wv.squaredNorm() + w.norm() * wa.norm()); break;
      case Kind::SquaredCross: b = 2.0 * an * an * (wv.squaredNorm() + w.norm() * wa.norm()); break;
    }
    return b * kPad + 1e-300;
  }

  /// The double-precision polynomial of g in s = t - c0.
  Polynomial polynomial(double c0) const {
    const Vec3 w0 = q_->position(c0) - vertex_, w1 = q_->velocity(c0), w2 = q_->a;
    const Vec3 A = A_.rounded();
    const double K = K_.value();
    Polynomial p;
    switch (kind_) {
      case Kind::Linear:
        p.c[2] = sign_ * 0.5 * A.dot(w2);
        p.c[1] = sign_ * A.dot(w1);
        p.c[0] = sign_ * A.dot(w0);
        break;
      case Kind::SquaredLinear: p = square_minus(A.dot(w0), A.dot(w1), 0.5 * A.dot(w2), K); break;
      case Kind::SquaredNorm:
      case Kind::SquaredCross: {
        const Vec3 x0 = kind_ == Kind::SquaredNorm ? w0 : A.cross(w0);
        const Vec3 x1 = kind_ == Kind::SquaredNorm ? w1 : A.cross(w1);
        const Vec3 x2 = kind_ == Kind::SquaredNorm ? w2 : A.cross(w2);
        p.c[4] = 0.25 * x2.squaredNorm();
        p.c[3] = x1.dot(x2);
        p.c[2] = x1.squaredNorm() + x0.dot(x2);
        p.c[1] = 2.0 * x0.dot(x1);
        p.c[0] = x0.squaredNorm() - K;
        break;
      }
    }
    return p;
  }

  /// A generous bound on the double-precision polynomial's error on [c0, c1] (scale of
  /// its terms times 256 eps, plus the errors carried by the piece's state): when the
  /// polynomial's minimum exceeds it, g > 0 on the whole range; when its maximum is below
  /// minus it, g < 0 on the whole range.
  double double_band(double c0, double c1) const {
    const double S = c1 - c0;
    const double M = (q_->position(c0) - vertex_).norm() + q_->velocity(c0).norm() * S + 0.5 * q_->a.norm() * S * S;
    const double P = std::max(piece_magnitude(*q_, c0), piece_magnitude(*q_, c1)) + vertex_.cwiseAbs().maxCoeff();
    const double carried = low_->edge_error + low_->start_error + low_->velocity_error * (c1 - q_->t0);
    const double an = kind_ == Kind::SquaredNorm ? 1.0 : a_norm_;
    const double r = std::sqrt(std::fabs(K_.value())) / std::max(an, 1e-300);
    if (kind_ == Kind::Linear) return 256.0 * kEps * an * (M + P) + 4.0 * an * carried;
    return 256.0 * kEps * an * an * (M + r) * (M + r + P) + 8.0 * an * an * (M + r) * carried +
           std::numeric_limits<double>::denorm_min();
  }

  double guess(double a, double b, bool in_left) const {
    const Polynomial& p = poly_;
    const Polynomial dp = p.derivative();
    const double c0 = c0_;
    return refine_sign_change(
        [&](double t, double* df) {
          *df = dp(t - c0);
          return p(t - c0);
        },
        a, b, in_left, std::numeric_limits<double>::quiet_NaN());
  }

  /// {t in [c0, c1] : g(t) <= 0}.
  SublevelSet sublevel_set(double c0, double c1) {
    c0_ = c0;
    poly_ = polynomial(c0);
    const MonotoneSplit split = monotone_split(poly_, 0.0, c1 - c0);
    double fmin = std::numeric_limits<double>::infinity(), fmax = -fmin;
    for (int i = 0; i < split.count; ++i) {
      const double g = poly_(split.x[i]);
      fmin = std::min(fmin, g);
      fmax = std::max(fmax, g);
    }
    const double band = double_band(c0, c1);
    if (fmin > band) return {};  // certainly out on the whole range
    if (fmax < -band) {          // certainly in on the whole range
      SublevelSet all;
      all.intervals[0] = {c0, c1};
      all.count = 1;
      return all;
    }
    return certified_sublevel_set(*this, split, c0, c1);
  }

 private:
  // Error of A . w: the inputs' errors and the double-double dot product's own.
  double linear_error(double wn, double ew) const {
    return std::sqrt(3.0) * kPad * (a_norm_ * ew + wn * a_error_) + 3.0 * ew * a_error_ + 16.0 * kU2 * a_norm_ * wn;
  }

  Kind kind_;
  const Piece* q_;
  const PieceLow* low_;
  Vec3 vertex_;
  DdVec3 A_;
  double a_error_;
  double sign_;
  Dd K_;
  double k_error_;
  double a_norm_, a_max_;
  double c0_ = 0.0;
  Polynomial poly_;
};

// The sets of one feature are intersected into `acc` (sorted, disjoint, closed).
class Feature {
 public:
  Feature(double c0, double c1, std::vector<RootInterval>& acc, std::vector<RootInterval>& scratch)
      : c0_(c0), c1_(c1), acc_(acc), scratch_(scratch) {
    acc_.clear();
    acc_.push_back({c0, c1});
  }
  /// Intersects with {t : g(t) <= 0}; returns false once the feature's set is empty.
  bool require(Condition g) {
    if (acc_.empty()) return false;
    const SublevelSet set = g.sublevel_set(c0_, c1_);
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
  double c0_, c1_;
  std::vector<RootInterval>& acc_;
  std::vector<RootInterval>& scratch_;
};

bool finite(const Vec3& x) { return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]); }

// The centre's path box over [u0, u1], grown by r and a rounding margin, misses the
// polygon's box.
bool boxes_apart(const Piece& q, double r, const StaticPolygon& poly, double u0, double u1) {
  Vec3 plo = poly.vertices[0], phi = poly.vertices[0];
  for (const Vec3& x : poly.vertices) {
    plo = plo.cwiseMin(x);
    phi = phi.cwiseMax(x);
  }
  const double s0 = u0 - q.t0, s1 = u1 - q.t0;
  const Vec3 &p = q.p, &v = q.v, &a = q.a;
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
    if (l - margin > phi[k] || h + margin < plo[k]) return true;
  }
  return false;
}

}  // namespace

void sphere_polygon_contacts(const Piece& q, const PieceLow& low, double r, const StaticPolygon& poly, double u0,
                             double u1, std::vector<ContactInterval>& out) {
  const std::size_t nv = poly.vertices.size();
  if (nv < 3 || !(u1 >= u0) || !(r >= 0.0) || !finite(q.p) || !finite(q.v) || !finite(q.a) ||
      !std::isfinite(q.t0) || !std::isfinite(u0) || !std::isfinite(u1))
    return;
  for (const Vec3& x : poly.vertices)
    if (!finite(x)) return;
  if (boxes_apart(q, r, poly, u0, u1)) return;

  using Kind = Condition::Kind;
  const Vec3& v0 = poly.vertices[0];
  const Dd r2 = two_prod(r, r);
  // The plane's normal N: the area normal sum_i (V_i - V_0) x (V_{i+1} - V_0) in
  // double-double, off by at most n_error per coordinate.
  DdVec3 N(Vec3::Zero());
  double n_terms = 0.0;
  for (std::size_t i = 1; i + 1 < nv; ++i) {
    const DdVec3 a = exact_difference(poly.vertices[i], v0), b = exact_difference(poly.vertices[i + 1], v0);
    N = N + cross(a, b);
    n_terms += norm(a) * norm(b);
  }
  const double n_error = (32.0 + 4.0 * static_cast<double>(nv)) * kU2 * n_terms;
  const double nn = norm(N), nm = max_abs(N);
  if (!(nn > 0.0)) return;

  std::vector<RootInterval> all, acc, scratch;
  auto collect = [&] { all.insert(all.end(), acc.begin(), acc.end()); };

  // Face: (N . w)^2 <= r^2 |N|^2 while the centre projects inside every edge, (N x e_i) . w_i >= 0.
  {
    const Dd N2 = dot(N, N);
    const double e_n2 = 2.0 * std::sqrt(3.0) * kPad * nn * n_error + 3.0 * n_error * n_error + 16.0 * kU2 * nn * nn;
    const Dd K = r2 * N2;
    const double e_k = r2.value() * e_n2 * kPad + 8.0 * kU2 * std::fabs(K.value());
    Feature f(u0, u1, acc, scratch);
    bool ok = f.require(Condition(Kind::SquaredLinear, q, low, v0, N, n_error, 1.0, K, e_k));
    for (std::size_t i = 0; ok && i < nv; ++i) {
      const Vec3& vi = poly.vertices[i];
      const DdVec3 e = exact_difference(poly.vertices[(i + 1) % nv], vi);
      const DdVec3 m = cross(N, e);  // inward: the vertices run counter-clockwise about N
      const double m_error = 2.0 * max_abs(e) * n_error * kPad + 16.0 * kU2 * nn * norm(e) + 2.0 * kU2 * nm * max_abs(e);
      ok = f.require(Condition(Kind::Linear, q, low, vi, m, m_error, -1.0, Dd(0.0), 0.0));
    }
    if (ok) collect();
  }
  // Vertices, and edges (line distance while projecting between the ends).
  for (std::size_t i = 0; i < nv; ++i) {
    const Vec3& vi = poly.vertices[i];
    const Vec3& vj = poly.vertices[(i + 1) % nv];
    {
      Feature f(u0, u1, acc, scratch);
      if (f.require(Condition(Kind::SquaredNorm, q, low, vi, DdVec3(Vec3::Zero()), 0.0, 1.0, r2, 0.0))) collect();
    }
    const DdVec3 e = exact_difference(vj, vi);
    const Dd e2 = dot(e, e);
    if (!(e2.value() > 0.0)) continue;
    const Dd K = r2 * e2;
    const double e_k = r2.value() * 16.0 * kU2 * e2.value() + 8.0 * kU2 * K.value();
    Feature f(u0, u1, acc, scratch);
    if (f.require(Condition(Kind::SquaredCross, q, low, vi, e, 0.0, 1.0, K, e_k)) &&
        f.require(Condition(Kind::Linear, q, low, vi, e, 0.0, -1.0, Dd(0.0), 0.0)) &&
        f.require(Condition(Kind::Linear, q, low, vj, e, 0.0, 1.0, Dd(0.0), 0.0)))
      collect();
  }
  if (all.empty()) return;

  std::sort(all.begin(), all.end(), [](const RootInterval& x, const RootInterval& y) { return x.lo < y.lo; });
  RootInterval cur = all[0];
  for (std::size_t k = 1; k < all.size(); ++k) {
    if (all[k].lo <= cur.hi) {
      cur.hi = std::max(cur.hi, all[k].hi);
    } else {
      out.push_back({cur.lo, cur.hi});
      cur = all[k];
    }
  }
  out.push_back({cur.lo, cur.hi});
}

void sphere_polygon_contacts(const Vec3& p, const Vec3& v, const Vec3& a, double t_ref, double r,
                             const StaticPolygon& poly, double u0, double u1, std::vector<ContactInterval>& out) {
  if (!std::isfinite(t_ref) || !(u1 >= u0)) return;
  // One piece with exact data (no trailing parts, no carried error).
  const Piece q{t_ref, std::max(t_ref, u1), p, v, a};
  const PieceLow exact{};
  sphere_polygon_contacts(q, exact, r, poly, u0, u1, out);
}

}  // namespace ccd
