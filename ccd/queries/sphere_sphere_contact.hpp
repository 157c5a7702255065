#pragma once
// Moving sphere vs moving sphere on one common quadratic piece of their motions.
//
// Each sphere's centre moves as c(s) = position + velocity s + acceleration s^2/2 for
// s in [0, duration] (units: the scene's, e.g. metres and seconds). Contact means
// |c_b(s) - c_a(s)| <= r_a + r_b (closed set; touching counts). With the relative
// d(s) = D0 + Dv s + Da s^2/2 and R = r_a + r_b the contact function is
//   f(s) = |d(s)|^2 - R^2,
// a quartic, or a QUADRATIC when Da == 0 exactly (shared acceleration, e.g. gravity, or
// linear motion): the lowest degree the motion needs is solved.
//  - Quadratic: the stable ray-vs-sphere form (ccd-math §2). The discriminant is computed
//    from the squared distance of the closest approach, B^2 - A C = A (R^2 - h^2) with
//    h = |D0 + Dv s*|, s* = -D0.Dv / |Dv|^2, which does not cancel for grazing
//    trajectories; the roots are q/A and C/q with q = -(B + sign(B) sqrt(disc)).
//  - Quartic: ccd/queries/polynomial_roots.hpp (critical points, monotone pieces,
//    safeguarded Newton); f itself is evaluated from the vector d(s), not the expanded
//    coefficients, so the minimum distance does not cancel.
//
// Tangency: a contact that only touches (double root) is reported as enter == exit. The
// tolerance (contact_tolerance below) is derived from machine epsilon and the sizes of
// the positions, relative motion and radii; see polynomial_roots.hpp for the rules.
// Guarantee: exact up to that rounding band (not conservative, not approximate).
// Degenerate cases: Dv == Da == 0 (no relative motion): the whole piece or nothing;
// coincident centres: Overlapping; duration < 0 or non-finite input: NoContact.
// No allocation.
#include <ccd/geometry/vec3.hpp>
#include <ccd/queries/polynomial_roots.hpp>

#include <limits>

namespace ccd {

/// One sphere at the start (s = 0) of the common piece.
struct MovingSphere {
  Vec3 position{Vec3::Zero()};
  Vec3 velocity{Vec3::Zero()};
  Vec3 acceleration{Vec3::Zero()};
  double radius = 0.0;
};

enum class ContactStatus {
  Hit,          ///< first contact at toi in (0, duration] (touching included)
  Overlapping,  ///< in contact at s = 0 (toi = 0)
  NoContact,    ///< separated for all of [0, duration] (toi = +infinity)
};

struct SphereSphereContact {
  ContactStatus status = ContactStatus::NoContact;
  double toi = std::numeric_limits<double>::infinity();
};

/// The contact function's rounding band, in units of f (length^2):
/// 16 eps (M + R) (M + R + P), M = |D0| + |Dv| S + |Da| S^2/2 (relative motion),
/// P = largest absolute coordinate of the two centres (the rounding of positions).
double contact_tolerance(const MovingSphere& a, const MovingSphere& b, double duration);

/// First time of contact in [0, duration].
SphereSphereContact sphere_sphere_first_contact(const MovingSphere& a, const MovingSphere& b, double duration);

/// Every maximal contact interval within [0, duration] (at most 3), times in s.
SublevelSet sphere_sphere_contact_intervals(const MovingSphere& a, const MovingSphere& b, double duration);

}  // namespace ccd
