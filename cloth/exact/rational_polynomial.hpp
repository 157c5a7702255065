#pragma once
// Univariate polynomials with exact rational coefficients (GMP), and the real-algebraic
// operations the exact CCD reference needs: square-free parts, greatest common divisors,
// Sturm root counting, root isolation on [0, 1] and the exact sign of a polynomial at a
// real root of another.
//
// Everything is exact: no tolerance, no floating point. Costs grow with the degree and the
// size of the coefficients; the reference is meant for tests and for checking query files,
// not for speed.
#include <gmpxx.h>

#include <vector>

namespace ccd::cloth {

/// c[0] + c[1] t + c[2] t^2 + ...; the zero polynomial has no coefficients. Operations keep
/// it trimmed (no zero leading coefficient).
class RationalPolynomial {
 public:
  RationalPolynomial() = default;
  explicit RationalPolynomial(std::vector<mpq_class> coefficients);
  /// a + b t.
  static RationalPolynomial linear(const mpq_class& a, const mpq_class& b);
  static RationalPolynomial constant(const mpq_class& a);

  bool is_zero() const { return c_.empty(); }
  /// -1 for the zero polynomial.
  int degree() const { return static_cast<int>(c_.size()) - 1; }
  const std::vector<mpq_class>& coefficients() const { return c_; }
  const mpq_class& leading() const { return c_.back(); }

  mpq_class operator()(const mpq_class& t) const;
  /// Sign (-1, 0, +1) of the value at t.
  int sign_at(const mpq_class& t) const;

  RationalPolynomial derivative() const;
  friend RationalPolynomial operator+(const RationalPolynomial& a, const RationalPolynomial& b);
  friend RationalPolynomial operator-(const RationalPolynomial& a, const RationalPolynomial& b);
  friend RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b);
  friend RationalPolynomial operator*(const mpq_class& s, const RationalPolynomial& a);
  friend bool operator==(const RationalPolynomial& a, const RationalPolynomial& b) { return a.c_ == b.c_; }

 private:
  void trim();
  std::vector<mpq_class> c_;
};

/// Quotient and remainder of a / b (b not zero).
void divide(const RationalPolynomial& a, const RationalPolynomial& b, RationalPolynomial& quotient,
            RationalPolynomial& remainder);
/// Monic greatest common divisor (zero when both are zero).
RationalPolynomial gcd(const RationalPolynomial& a, const RationalPolynomial& b);
/// p / gcd(p, p'): the same roots, each simple (p not zero).
RationalPolynomial square_free(const RationalPolynomial& p);

/// Sturm sequence of a square-free polynomial: p, p', then negated remainders.
std::vector<RationalPolynomial> sturm_sequence(const RationalPolynomial& p);
/// Number of distinct roots in (a, b] (a < b, p(a) != 0) of the square-free polynomial
/// whose Sturm sequence is `sturm`.
int count_roots(const std::vector<RationalPolynomial>& sturm, const mpq_class& a, const mpq_class& b);

/// A real root r of a square-free polynomial q, isolated: a < r < b, r is q's only root in
/// [a, b] and q(a), q(b) are not zero (so they have opposite signs).
struct IsolatedRoot {
  mpq_class a, b;
};

/// The roots of the square-free q strictly inside (0, 1), in increasing order, each in an
/// isolating interval; the intervals are disjoint and none touches 0 or 1. q(0) and q(1)
/// must not be zero.
std::vector<IsolatedRoot> isolate_roots_in_unit_interval(const RationalPolynomial& q);

/// Sign (-1, 0, +1) of g at the root isolated by `root` of the square-free q. May narrow
/// `root` (it stays an isolating interval of the same root).
int sign_at_root(const RationalPolynomial& g, const RationalPolynomial& q, IsolatedRoot& root);

}  // namespace ccd::cloth
