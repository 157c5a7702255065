#pragma once
// The point of the convex hull of a few points in R^3 nearest to the origin (the
// Gilbert-Johnson-Keerthi distance iteration, with the nearest point of each small simplex
// found by trying its faces). The triangle CCD kernel uses it as a direction n to exclude
// a box of parameters: F's image of the box lies in the hull of its corner values, and
// when the origin is outside that hull, n.F is positive on all of it for n the nearest
// point. The result only steers a test that carries its own proof (excluded_along in
// parameter_box.hpp), so it is computed in doubles (with fma for the direction to an edge).
namespace ccd::cloth::detail {

/// Points p[0..n-1] (1 <= n <= 10). Returns false when the origin is in the hull or
/// nearly so (no direction), else writes the nearest point (approximately) to out, or,
/// when it lies inside an edge of the hull, a positive multiple of it computed with
/// relative accuracy (the edge may pass the origin far closer than its points' size).
bool hull_nearest_point(const double (*p)[3], int n, double (&out)[3]);

}  // namespace ccd::cloth::detail
