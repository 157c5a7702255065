#pragma once
// The one definition of "two spheres touch at an instant", shared by the ground truth's
// rounding band, the discrete narrow phase (ccd/narrow/sphere_sphere_narrow.hpp) and
// therefore by the runner and the benchmarks, which call the narrow phase.
//
// Touching: f = |c_a - c_b|^2 - (r_a + r_b)^2 <= contact_tolerance over a zero duration
// (ccd/queries/sphere_sphere_contact.hpp): the contact function within the ground truth's
// own rounding band, so that a sample test and the truth agree on what touching means.
// Units: the scene's lengths. Closed: exact touching counts. Coincident centres touch.
// Non-finite input: false (NaN compares false).
#include <ccd/geometry/vec3.hpp>

namespace ccd {

bool spheres_touch(const Vec3& centre_a, double radius_a, const Vec3& centre_b, double radius_b);

}  // namespace ccd
