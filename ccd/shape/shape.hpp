#pragma once
// A body's shape: a convex set in the body frame, whose origin is the body's centre of
// mass and centre of rotation (docs/rigid_bodies.md).
//
//  - sphere:  the ball of `radius` about the origin;
//  - capsule: the segment from (-half_length, 0, 0) to (+half_length, 0, 0) grown by
//             `radius` (a stick);
//  - box:     [-h, h] on each body axis, h = half_extents (a crate; a plate when thin);
//  - hull:    the convex hull of `points` (at least 4, spanning a volume: a rock).
// Every shape is also a ConvexProxy (points + radius) for the generic narrow phase.
//
// enclosing_radius: the radius of the smallest ball about the origin that holds the shape
// in every orientation (sphere r, capsule half_length + r, box |h|, hull max |p|), rounded
// up by a few ulps so that it is never below the exact value. Bounds, broad phases and
// walls see a shaped body as this ball.
#include <ccd/geometry/vec3.hpp>
#include <ccd/shape/convex_proxy.hpp>
#include <ccd/shape/shape_kind.hpp>

#include <string>
#include <vector>

namespace ccd {

struct Shape {
  std::string name;                ///< as the scene names it (unique in a scene)
  ShapeKind kind = ShapeKind::Sphere;
  double radius = 0.0;             ///< sphere, capsule (metres, > 0)
  double half_length = 0.0;        ///< capsule (metres, > 0)
  Vec3 half_extents{Vec3::Zero()}; ///< box (metres, each > 0)
  std::vector<Vec3> points;        ///< hull: as given; other kinds: the proxy's points

  /// Fills `points` for sphere, capsule and box from their sizes (hull: unchanged).
  void build_points();
  /// The proxy view of this shape (valid while the shape lives and is not changed).
  ConvexProxy proxy() const { return {points, kind == ShapeKind::Sphere || kind == ShapeKind::Capsule ? radius : 0.0}; }
  /// See the header comment.
  double enclosing_radius() const;
};

/// Makers for code and tests (points already built).
Shape make_sphere_shape(double radius, std::string name = "sphere");
Shape make_capsule_shape(double half_length, double radius, std::string name = "capsule");
Shape make_box_shape(const Vec3& half_extents, std::string name = "box");
Shape make_hull_shape(std::vector<Vec3> points, std::string name = "hull");

/// Why a hull's points do not span a volume, or empty when they do: fewer than 4 points,
/// all points coincide, all on one line, all on one plane. A point counts as off a line or
/// plane when it is further from it than 1e-9 x the largest |point| (far above rounding,
/// far below any shape one would simulate).
std::string hull_degeneracy(const std::vector<Vec3>& points);

}  // namespace ccd
