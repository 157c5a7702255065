#pragma once
// A proof that F(t, a, b) = 0 somewhere in the parameter domain (the vertex-face or
// edge-edge difference vector, parameter_box.hpp): the primitives touch.
//
// Method (an interval Newton test in the form of the Poincare-Miranda theorem). Newton's
// method from a start point finds an approximate root x* of F; A is the inverse of F's
// Jacobian there, and G = A F. Around x* a box of half-width r (a power of two, so its
// corners are dyadic with at most 52 fractional bits and the corner values of F carry the
// bound of parameter_box.hpp) is tested: for each parameter i, G_i is below -bound_i on
// every corner of the face x_i = lo and above bound_i on every corner of x_i = hi (or the
// reverse). G_i is multilinear, so on each face it is spanned by the face's corners, and
// Poincare-Miranda gives a zero of G in the box; the strict inequalities make A regular
// (a singular A maps the box into a plane, whose zero would not be surrounded), so F has
// the same zero. bound_i = |A_i|_1 err (F's corner error) plus 4 eps sum_k |A_ik f_k| (the
// rounded dot product), rounded up. The box must lie in the domain: [0, 1]^3, and for
// vertex-face a + b <= 1 at its far corner.
//
// A root on the domain's boundary (contact exactly at t = 0 or 1, a vertex on an edge)
// or where F's Jacobian is singular (tangent or coplanar contact) is not proved: the
// caller decides such queries otherwise.
#include <cloth/ccd/linear_query.hpp>

namespace ccd::cloth::detail {

/// q: the query as the kernel searches it; err: the error bound of one component of a
/// corner value of F (parameter_box.hpp); start: (t, a, b) to start Newton from. On
/// success, t_upper gets the largest t of the proving box (a contact at a t <= t_upper).
bool proves_root(PrimitivePair kind, const LinearQuery& q, double err, const double (&start)[3],
                 double& t_upper);

}  // namespace ccd::cloth::detail
