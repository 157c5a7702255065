#pragma once
// The exact reference for vertex-face and edge-edge CCD under linear motion: rational
// arithmetic only (GMP), no tolerance. It decides whether the two primitives come within
// a given distance of each other (distance <= separation, touching included) at some
// time t in [0, 1].
//
// Method. The distance between two simplices is reached by one pair of their features
// (vertex-face: the face interior, an edge or a corner; edge-edge: the two interiors, an
// end point against the other edge, or two end points). For each pair of features,
// "within the separation" is a conjunction of polynomial sign conditions in t (for the
// face interior: |n|^2 > 0, sep^2 |n|^2 - (n.w)^2 >= 0 and the three barycentric numerators
// >= 0, with n the triangle's unnormalised normal). A conjunction holds somewhere in
// [0, 1] iff it holds at t = 0, t = 1, a real root of one of its polynomials, or a rational
// point of each open interval between consecutive roots. Roots are isolated with Sturm
// sequences and signs at roots are decided exactly (ccd/cloth/exact/rational_polynomial).
// With separation 0 the plane condition is an equality: only the roots of the
// coplanarity cubic are visited.
//
// Coordinates are rationals (the benchmark's numerator/denominator columns); doubles
// convert exactly.
#include <cloth/ccd/linear_query.hpp>

#include <gmpxx.h>

#include <array>

namespace ccd::cloth {

struct RationalQuery {
  std::array<std::array<mpq_class, 3>, 8> x;  ///< same row order as LinearQuery
};

/// The exact rationals of a double query.
RationalQuery to_rational(const LinearQuery& q);

/// True iff the primitives' distance is <= sqrt(separation_squared) at some t in [0, 1].
/// separation_squared >= 0.
bool exact_contact(PrimitivePair kind, const RationalQuery& q, const mpq_class& separation_squared);

}  // namespace ccd::cloth
