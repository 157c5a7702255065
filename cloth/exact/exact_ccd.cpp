#include "exact_ccd.hpp"

#include <cloth/exact/rational_polynomial.hpp>

#include <vector>

namespace ccd::cloth {

RationalQuery to_rational(const LinearQuery& q) {
  RationalQuery r;
  for (std::size_t i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) r.x[i][static_cast<std::size_t>(k)] = mpq_class(q.x[i][k]);  // exact
  return r;
}

namespace {

using Poly = RationalPolynomial;
using PVec = std::array<Poly, 3>;

PVec operator-(const PVec& a, const PVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Poly dot(const PVec& a, const PVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
PVec cross(const PVec& a, const PVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

enum class Rel { Zero, NonNegative, Positive };
struct Condition {
  Poly p;
  Rel rel;
};

bool holds(int sign, Rel rel) {
  switch (rel) {
    case Rel::Zero: return sign == 0;
    case Rel::NonNegative: return sign >= 0;
    case Rel::Positive: return sign > 0;
  }
  return false;
}

bool holds_at(const std::vector<Condition>& cs, const mpq_class& t) {
  for (const Condition& c : cs)
    if (!holds(c.p.sign_at(t), c.rel)) return false;
  return true;
}

bool holds_at_root(const std::vector<Condition>& cs, const Poly& q, IsolatedRoot& root) {
  for (const Condition& c : cs)
    if (!holds(sign_at_root(c.p, q, root), c.rel)) return false;
  return true;
}

// Removes the roots 0 and 1 of a square-free q (they are sampled separately).
Poly without_unit_ends(Poly q) {
  Poly quotient, remainder;
  if (q.degree() >= 1 && q.sign_at(0) == 0) {
    divide(q, Poly::linear(0, 1), quotient, remainder);
    q = quotient;
  }
  if (q.degree() >= 1 && q.sign_at(1) == 0) {
    divide(q, Poly::linear(-1, 1), quotient, remainder);
    q = quotient;
  }
  return q;
}

// Does the conjunction hold at some t in [0, 1]?
bool exists_time(std::vector<Condition> cs) {
  std::vector<Condition> live;
  const Poly* equality = nullptr;
  for (Condition& c : cs) {
    if (c.p.degree() <= 0) {  // constant: decided now
      if (!holds(c.p.is_zero() ? 0 : sgn(c.p.leading()), c.rel)) return false;
      continue;
    }
    live.push_back(std::move(c));
  }
  if (live.empty()) return true;
  if (holds_at(live, 0) || holds_at(live, 1)) return true;
  for (const Condition& c : live)
    if (c.rel == Rel::Zero) equality = &c.p;
  Poly q;
  if (equality != nullptr) {
    q = square_free(*equality);  // only its roots can satisfy the conjunction
  } else {
    q = Poly::constant(1);
    for (const Condition& c : live) {
      const Poly s = square_free(c.p);
      Poly extra, rem;
      divide(s, gcd(q, s), extra, rem);
      q = q * extra;
    }
  }
  q = without_unit_ends(q);
  std::vector<IsolatedRoot> roots = isolate_roots_in_unit_interval(q);
  if (equality == nullptr) {
    // One rational point in each open interval between consecutive roots (and 0, 1).
    if (roots.empty() && holds_at(live, mpq_class(1, 2))) return true;
    for (const IsolatedRoot& r : roots)
      if (holds_at(live, r.a) || holds_at(live, r.b)) return true;
  }
  for (IsolatedRoot& r : roots)
    if (holds_at_root(live, q, r)) return true;
  return false;
}

// Polynomial positions of the query's points: x_i(t) = x_i0 + t (x_i1 - x_i0).
std::array<PVec, 4> positions(const RationalQuery& q) {
  std::array<PVec, 4> p;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t k = 0; k < 3; ++k) p[i][k] = Poly::linear(q.x[i][k], q.x[i + 4][k] - q.x[i][k]);
  return p;
}

// "sep2 * scale - square >= 0", or "square == 0" when sep2 = 0.
Condition within(const mpq_class& sep2, const Poly& square, const Poly& scale) {
  if (sgn(sep2) == 0) return {square, Rel::Zero};
  return {sep2 * scale - square, Rel::NonNegative};
}

bool point_point(const PVec& p, const PVec& a, const mpq_class& sep2) {
  const PVec d = p - a;
  return exists_time({within(sep2, dot(d, d), Poly::constant(1))});
}

// p within the separation of the closed segment [a, b] at a point whose projection lies on
// the segment (b != a); the end points themselves are point_point's.
bool point_segment(const PVec& p, const PVec& a, const PVec& b, const mpq_class& sep2) {
  const PVec d = b - a, w = p - a, x = cross(w, d);
  const Poly dd = dot(d, d), wd = dot(w, d);
  return exists_time({{dd, Rel::Positive}, within(sep2, dot(x, x), dd), {wd, Rel::NonNegative}, {dd - wd, Rel::NonNegative}});
}

bool vertex_face(const std::array<PVec, 4>& x, const mpq_class& sep2) {
  const PVec &p = x[0], &f0 = x[1], &f1 = x[2], &f2 = x[3];
  for (const PVec* f : {&f0, &f1, &f2})
    if (point_point(p, *f, sep2)) return true;
  if (point_segment(p, f0, f1, sep2) || point_segment(p, f1, f2, sep2) || point_segment(p, f2, f0, sep2)) return true;
  const PVec e1 = f1 - f0, e2 = f2 - f0, w = p - f0, n = cross(e1, e2);
  const Poly nn = dot(n, n), c = dot(n, w), a = dot(cross(w, e2), n), b = dot(cross(e1, w), n);
  // With sep2 = 0 the plane condition is the coplanarity cubic c = 0 (degree 3, not c^2).
  const Condition plane = sgn(sep2) == 0 ? Condition{c, Rel::Zero} : within(sep2, c * c, nn);
  return exists_time({{nn, Rel::Positive}, plane, {a, Rel::NonNegative}, {b, Rel::NonNegative}, {nn - a - b, Rel::NonNegative}});
}

bool edge_edge(const std::array<PVec, 4>& x, const mpq_class& sep2) {
  const PVec &a0 = x[0], &a1 = x[1], &b0 = x[2], &b1 = x[3];
  for (const PVec* a : {&a0, &a1})
    for (const PVec* b : {&b0, &b1})
      if (point_point(*a, *b, sep2)) return true;
  if (point_segment(a0, b0, b1, sep2) || point_segment(a1, b0, b1, sep2) || point_segment(b0, a0, a1, sep2) ||
      point_segment(b1, a0, a1, sep2))
    return true;
  const PVec da = a1 - a0, db = b1 - b0, r = b0 - a0, m = cross(da, db);
  const Poly mm = dot(m, m), c = dot(m, r), s = dot(cross(r, db), m), u = dot(cross(r, da), m);
  const Condition plane = sgn(sep2) == 0 ? Condition{c, Rel::Zero} : within(sep2, c * c, mm);
  return exists_time({{mm, Rel::Positive}, plane, {s, Rel::NonNegative}, {mm - s, Rel::NonNegative},
                      {u, Rel::NonNegative}, {mm - u, Rel::NonNegative}});
}

}  // namespace

bool exact_contact(PrimitivePair kind, const RationalQuery& q, const mpq_class& separation_squared) {
  const std::array<PVec, 4> x = positions(q);
  return kind == PrimitivePair::VertexFace ? vertex_face(x, separation_squared) : edge_edge(x, separation_squared);
}

}  // namespace ccd::cloth
