#pragma once
// Moving sphere vs moving sphere on one common quadratic piece of their motions.
//
// Each sphere's centre moves as c(s) = position + velocity s + acceleration s^2/2 for
// s in [0, duration] (units: the scene's, e.g. metres and seconds). Contact means
// |c_b(s) - c_a(s)| <= r_a + r_b (closed set; touching counts). The inputs are taken as
// exact; the answer is that of ccd/queries/pair_motion.hpp, the ground truth's own
// contact function: the critical points of f(s) = |d(s)|^2 - R^2 split [0, duration]
// into monotone pieces (closed form when the accelerations are equal, so that f is a
// quadratic; the quartic's cubic f' otherwise), every sign is decided in double-double
// with a certified error bound, and roots are narrowed to adjacent doubles.
//
// Tangency: a contact that only touches (double root) is reported as enter == exit;
// only when |f| at the minimum is inside the error bound (about 1e-32 relative) is a
// minimum taken as touching. A miss by one ulp of the data is a miss.
// Degenerate cases: no relative motion: the whole piece or nothing; coincident centres:
// Overlapping; duration < 0 or non-finite input: Miss. No allocation.
#include <ccd/geometry/vec3.hpp>
#include <ccd/queries/polynomial_roots.hpp>
#include <ccd/queries/query_status.hpp>

#include <limits>

namespace ccd {

/// One sphere at the start (s = 0) of the common piece.
struct MovingSphere {
  Vec3 position{Vec3::Zero()};
  Vec3 velocity{Vec3::Zero()};
  Vec3 acceleration{Vec3::Zero()};
  double radius = 0.0;
};

/// Hit (first contact at toi in (0, duration], touching included), Overlapping (in
/// contact at s = 0, toi = 0) or Miss (separated for all of [0, duration], toi = +inf);
/// the shared vocabulary of ccd/queries/query_status.hpp.
using ContactStatus = QueryStatus;

struct SphereSphereContact {
  ContactStatus status = ContactStatus::Miss;
  double toi = std::numeric_limits<double>::infinity();
};

/// First time of contact in [0, duration].
SphereSphereContact sphere_sphere_first_contact(const MovingSphere& a, const MovingSphere& b, double duration);

/// Every maximal contact interval within [0, duration] (at most 3), times in s.
SublevelSet sphere_sphere_contact_intervals(const MovingSphere& a, const MovingSphere& b, double duration);

}  // namespace ccd
