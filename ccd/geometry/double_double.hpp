#pragma once
// Double-double arithmetic: a value hi + lo with |lo| <= ulp(hi)/2, about 106 bits.
//
// Used where the ground truth must not lose the data's own digits: trajectory states at
// breaks, the relative position of two bodies, and the contact function near tangency.
// Building blocks are the error-free transformations (Knuth's two-sum, Dekker's product
// through fma); the compound operations follow the "accurate" double-double algorithms
// (Joldes, Muller, Popescu 2017) with relative error below 3 u^2 for + and - and 6 u^2
// for *, u = 2^-53. The project is compiled with -ffp-contract=off so that the compiler
// cannot fuse or reorder the additions these rely on.
#include <ccd/geometry/vec3.hpp>

#include <cmath>

namespace ccd {

/// Unit roundoff of double (half an ulp of 1).
inline constexpr double kUnitRoundoff = 0x1p-53;

struct Dd {
  double hi = 0.0;
  double lo = 0.0;

  Dd() = default;
  constexpr Dd(double h) : hi(h) {}  // NOLINT: implicit on purpose
  constexpr Dd(double h, double l) : hi(h), lo(l) {}
  double value() const { return hi + lo; }
};

/// a + b exactly as hi + lo (Knuth).
inline Dd two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  const double e = (a - (s - bb)) + (b - bb);
  return {s, e};
}

/// a + b exactly when |a| >= |b| or a == 0 (Dekker).
inline Dd fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

/// a * b exactly as hi + lo (fma).
inline Dd two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

inline Dd operator+(const Dd& x, const Dd& y) {
  const Dd s = two_sum(x.hi, y.hi);
  const Dd t = two_sum(x.lo, y.lo);
  Dd v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, t.lo + v.lo);
}
inline Dd operator-(const Dd& x) { return {-x.hi, -x.lo}; }
inline Dd operator-(const Dd& x, const Dd& y) { return x + (-y); }

inline Dd operator*(const Dd& x, const Dd& y) {
  const Dd p = two_prod(x.hi, y.hi);
  const double t = x.hi * y.lo + x.lo * y.hi;
  return fast_two_sum(p.hi, p.lo + t);
}
inline Dd operator*(const Dd& x, double y) {
  const Dd p = two_prod(x.hi, y);
  return fast_two_sum(p.hi, p.lo + x.lo * y);
}

/// A point or vector with double-double coordinates.
struct DdVec3 {
  Dd x[3];

  DdVec3() = default;
  explicit DdVec3(const Vec3& v) : x{Dd(v[0]), Dd(v[1]), Dd(v[2])} {}
  DdVec3(const Vec3& hi, const Vec3& lo) : x{Dd(hi[0], lo[0]), Dd(hi[1], lo[1]), Dd(hi[2], lo[2])} {}
  Dd& operator[](int k) { return x[k]; }
  const Dd& operator[](int k) const { return x[k]; }
  Vec3 hi() const { return {x[0].hi, x[1].hi, x[2].hi}; }
  Vec3 lo() const { return {x[0].lo, x[1].lo, x[2].lo}; }
  /// Each coordinate rounded to the nearest double.
  Vec3 rounded() const { return {x[0].value(), x[1].value(), x[2].value()}; }
};

inline DdVec3 operator+(const DdVec3& a, const DdVec3& b) {
  DdVec3 r;
  for (int k = 0; k < 3; ++k) r[k] = a[k] + b[k];
  return r;
}
inline DdVec3 operator-(const DdVec3& a, const DdVec3& b) {
  DdVec3 r;
  for (int k = 0; k < 3; ++k) r[k] = a[k] - b[k];
  return r;
}
inline DdVec3 operator*(const DdVec3& a, const Dd& s) {
  DdVec3 r;
  for (int k = 0; k < 3; ++k) r[k] = a[k] * s;
  return r;
}
inline Dd dot(const DdVec3& a, const DdVec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace ccd
