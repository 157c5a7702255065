#pragma once
// The surface of a point set's convex hull as outward triangles, for the hull's mass
// properties (ccd/shape/mass_properties.hpp). Incremental: a first tetrahedron of extreme
// points, then each further point that lies outside a face by more than 1e-9 x the set's
// radius replaces the faces it sees with a cone from their horizon to it. Points on the
// surface within that tolerance add no face (the volume integrals do not change by more
// than the tolerance). O(points x faces) time: about 5e7 face tests for 5,000 points on a
// sphere (about a second), so callers bound the point count (kMaxMassPropertyPoints).
#include <ccd/geometry/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace ccd {

/// The hull points whose mass properties are computed when a scene loads (a free-spinning
/// hull without `inertia`); a larger hull is refused there, naming its size.
inline constexpr std::size_t kMaxMassPropertyPoints = 5000;

/// The hull's faces, each (a, b, c) counter-clockwise seen from outside. Empty when the
/// points span no volume (coincident, collinear or coplanar: ccd::hull_degeneracy).
std::vector<std::array<Vec3, 3>> convex_hull_triangles(const std::vector<Vec3>& points);

}  // namespace ccd
