#include "rational_polynomial.hpp"

#include <cassert>
#include <stdexcept>
#include <utility>

namespace ccd::cloth {

RationalPolynomial::RationalPolynomial(std::vector<mpq_class> coefficients) : c_(std::move(coefficients)) { trim(); }

RationalPolynomial RationalPolynomial::linear(const mpq_class& a, const mpq_class& b) {
  return RationalPolynomial({a, b});
}

RationalPolynomial RationalPolynomial::constant(const mpq_class& a) { return RationalPolynomial({a}); }

void RationalPolynomial::trim() {
  while (!c_.empty() && sgn(c_.back()) == 0) c_.pop_back();
}

mpq_class RationalPolynomial::operator()(const mpq_class& t) const {
  mpq_class v = 0;
  for (std::size_t i = c_.size(); i-- > 0;) v = v * t + c_[i];  // Horner, exact
  return v;
}

int RationalPolynomial::sign_at(const mpq_class& t) const { return sgn((*this)(t)); }

RationalPolynomial RationalPolynomial::derivative() const {
  std::vector<mpq_class> d;
  for (std::size_t i = 1; i < c_.size(); ++i) d.push_back(c_[i] * static_cast<long>(i));
  return RationalPolynomial(std::move(d));
}

RationalPolynomial operator+(const RationalPolynomial& a, const RationalPolynomial& b) {
  std::vector<mpq_class> r(std::max(a.c_.size(), b.c_.size()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i < a.c_.size()) r[i] += a.c_[i];
    if (i < b.c_.size()) r[i] += b.c_[i];
  }
  return RationalPolynomial(std::move(r));
}

RationalPolynomial operator-(const RationalPolynomial& a, const RationalPolynomial& b) {
  return a + mpq_class(-1) * b;
}

RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<mpq_class> r(a.c_.size() + b.c_.size() - 1);
  for (std::size_t i = 0; i < a.c_.size(); ++i)
    for (std::size_t j = 0; j < b.c_.size(); ++j) r[i + j] += a.c_[i] * b.c_[j];
  return RationalPolynomial(std::move(r));
}

RationalPolynomial operator*(const mpq_class& s, const RationalPolynomial& a) {
  std::vector<mpq_class> r = a.c_;
  for (mpq_class& x : r) x *= s;
  return RationalPolynomial(std::move(r));
}

void divide(const RationalPolynomial& a, const RationalPolynomial& b, RationalPolynomial& quotient,
            RationalPolynomial& remainder) {
  if (b.is_zero()) throw std::invalid_argument("RationalPolynomial: division by zero");
  std::vector<mpq_class> r = a.coefficients();
  const std::vector<mpq_class>& d = b.coefficients();
  const int db = b.degree();
  std::vector<mpq_class> q(a.degree() >= db ? static_cast<std::size_t>(a.degree() - db + 1) : 0);
  for (int k = a.degree(); k >= db; --k) {
    const mpq_class f = r[static_cast<std::size_t>(k)] / d.back();
    q[static_cast<std::size_t>(k - db)] = f;
    if (sgn(f) == 0) continue;
    for (int j = 0; j <= db; ++j) r[static_cast<std::size_t>(k - db + j)] -= f * d[static_cast<std::size_t>(j)];
  }
  if (db >= 0 && r.size() > static_cast<std::size_t>(db)) r.resize(static_cast<std::size_t>(db));
  quotient = RationalPolynomial(std::move(q));
  remainder = RationalPolynomial(std::move(r));
}

namespace {
RationalPolynomial monic(const RationalPolynomial& p) {
  if (p.is_zero()) return p;
  return mpq_class(1 / p.leading()) * p;
}
}  // namespace

RationalPolynomial gcd(const RationalPolynomial& a, const RationalPolynomial& b) {
  RationalPolynomial x = a, y = b, q, r;
  while (!y.is_zero()) {
    divide(x, y, q, r);
    x = std::move(y);
    y = monic(r);  // keeps coefficients from growing as fast
  }
  return monic(x);
}

RationalPolynomial square_free(const RationalPolynomial& p) {
  assert(!p.is_zero());
  if (p.degree() <= 1) return monic(p);
  RationalPolynomial q, r;
  divide(p, gcd(p, p.derivative()), q, r);
  return monic(q);
}

std::vector<RationalPolynomial> sturm_sequence(const RationalPolynomial& p) {
  std::vector<RationalPolynomial> s{p};
  if (p.degree() < 1) return s;
  s.push_back(p.derivative());
  RationalPolynomial q, r;
  while (true) {
    divide(s[s.size() - 2], s.back(), q, r);
    if (r.is_zero()) break;
    // -r scaled by a positive constant keeps the sign pattern: make it monic up to sign.
    const mpq_class scale = -1 / abs(r.leading());
    s.push_back(scale * r);
  }
  return s;
}

namespace {
int sign_variations(const std::vector<RationalPolynomial>& s, const mpq_class& t) {
  int count = 0, last = 0;
  for (const RationalPolynomial& p : s) {
    const int sg = p.sign_at(t);
    if (sg == 0) continue;
    if (last != 0 && sg != last) ++count;
    last = sg;
  }
  return count;
}
}  // namespace

int count_roots(const std::vector<RationalPolynomial>& sturm, const mpq_class& a, const mpq_class& b) {
  return sign_variations(sturm, a) - sign_variations(sturm, b);
}

namespace {
// A split point strictly inside (a, b) where q is not zero: the midpoint, or else one of
// the points a + k (b - a) / (n + 2), of which at most deg q are roots.
mpq_class split_point(const RationalPolynomial& q, const mpq_class& a, const mpq_class& b) {
  mpq_class m = (a + b) / 2;
  if (q.sign_at(m) != 0) return m;
  const int n = q.degree() + 2;
  for (int k = 1; k < n; ++k) {
    m = a + (b - a) * k / n;
    if (q.sign_at(m) != 0) return m;
  }
  throw std::logic_error("split_point: no non-root found");  // impossible: > deg q candidates
}

void isolate(const RationalPolynomial& q, const std::vector<RationalPolynomial>& sturm, const mpq_class& a,
             const mpq_class& b, int n, std::vector<IsolatedRoot>& out) {
  if (n == 0) return;
  if (n == 1) {
    out.push_back({a, b});
    return;
  }
  const mpq_class m = split_point(q, a, b);
  const int left = count_roots(sturm, a, m);
  isolate(q, sturm, a, m, left, out);
  isolate(q, sturm, m, b, n - left, out);
}

// Narrows (a, b) to an isolating interval strictly inside it on both sides.
void shrink_inside(const RationalPolynomial& q, IsolatedRoot& root) {
  const mpq_class a0 = root.a, b0 = root.b;
  const int sa = q.sign_at(root.a);
  while (root.a == a0 || root.b == b0) {
    const mpq_class m = split_point(q, root.a, root.b);
    if (q.sign_at(m) == sa) {
      root.a = m;
    } else {
      root.b = m;
    }
  }
}
}  // namespace

std::vector<IsolatedRoot> isolate_roots_in_unit_interval(const RationalPolynomial& q) {
  std::vector<IsolatedRoot> out;
  if (q.degree() < 1) return out;
  assert(q.sign_at(0) != 0 && q.sign_at(1) != 0);
  const std::vector<RationalPolynomial> sturm = sturm_sequence(q);
  isolate(q, sturm, 0, 1, count_roots(sturm, 0, 1), out);
  for (IsolatedRoot& r : out) shrink_inside(q, r);
  return out;
}

int sign_at_root(const RationalPolynomial& g, const RationalPolynomial& q, IsolatedRoot& root) {
  if (g.is_zero()) return 0;
  if (g.degree() == 0) return sgn(g.leading());
  // g(r) = 0 iff h = gcd(g, q) vanishes at r. h divides the square-free q, so it is
  // square-free and r is its only possible root in (a, b): it vanishes there iff it
  // changes sign between a and b (h(a), h(b) != 0 because q(a), q(b) != 0).
  const RationalPolynomial h = gcd(g, q);
  if (h.degree() >= 1 && h.sign_at(root.a) * h.sign_at(root.b) < 0) return 0;
  // g(r) != 0: narrow (a, b) until g has no root in [a, b]; g's sign there is g(r)'s.
  const RationalPolynomial gs = square_free(g);
  const std::vector<RationalPolynomial> sturm = sturm_sequence(gs);
  const int sq = q.sign_at(root.a);
  while (true) {
    const int ga = gs.sign_at(root.a);
    if (ga != 0 && gs.sign_at(root.b) != 0 && count_roots(sturm, root.a, root.b) == 0) return g.sign_at(root.a);
    const mpq_class m = (root.a + root.b) / 2;
    const int s = q.sign_at(m);
    if (s == 0) return g.sign_at(m);  // r = m, rational
    if (s == sq) {
      root.a = m;
    } else {
      root.b = m;
    }
  }
}

}  // namespace ccd::cloth
