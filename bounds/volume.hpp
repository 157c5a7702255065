#pragma once
// The shapes a bound tests for one body (Bound::volumes): what the viewer draws and what
// the tests check against the body's motion. Four kinds:
//   Box          an axis-aligned box [a, b]
//   Sphere       a ball of centre a and radius `radius`
//   Capsule      the points within `radius` of the segment [a, b]
//   OrientedBox  centre a, half-widths b along the columns of `axes`
// Each covers the time span [t0, t1] (the body's window, or one sub-interval of it for the
// bounds that cut the window into pieces).
#include <ccd/geometry/aabb.hpp>
#include <ccd/geometry/vec3.hpp>

#include <Eigen/Core>
#include <cstdint>
#include <string_view>

namespace ccd {

struct Volume {
  enum class Kind : std::uint8_t { Box, Sphere, Capsule, OrientedBox };
  Kind kind = Kind::Box;
  double t0 = 0.0;  ///< the time span the volume covers
  double t1 = 0.0;
  Vec3 a{Vec3::Zero()};  ///< Box: lo; Sphere, OrientedBox: centre; Capsule: first end
  Vec3 b{Vec3::Zero()};  ///< Box: hi; Capsule: second end; OrientedBox: half-widths
  double radius = 0.0;   ///< Sphere, Capsule
  Eigen::Matrix3d axes{Eigen::Matrix3d::Identity()};  ///< OrientedBox: orthonormal columns

  static Volume box(const Aabb& box, double t0, double t1) { return {Kind::Box, t0, t1, box.lo, box.hi}; }
  static Volume sphere(const Vec3& centre, double r, double t0, double t1) {
    return {Kind::Sphere, t0, t1, centre, Vec3::Zero(), r};
  }
  static Volume capsule(const Vec3& p0, const Vec3& p1, double r, double t0, double t1) {
    return {Kind::Capsule, t0, t1, p0, p1, r};
  }
  static Volume oriented_box(const Vec3& centre, const Eigen::Matrix3d& axes, const Vec3& half, double t0, double t1) {
    return {Kind::OrientedBox, t0, t1, centre, half, 0.0, axes};
  }

  /// The world AABB that encloses the volume.
  Aabb hull() const;
  /// Whether the ball of centre x and radius r lies inside the volume, up to `tolerance`
  /// (metres) on every face.
  bool contains(const Vec3& x, double r, double tolerance) const;
};

/// "box", "sphere", "capsule", "oriented_box" (the viewer's data, docs/viewer.md).
constexpr std::string_view to_string(Volume::Kind k) {
  switch (k) {
    case Volume::Kind::Box: return "box";
    case Volume::Kind::Sphere: return "sphere";
    case Volume::Kind::Capsule: return "capsule";
    case Volume::Kind::OrientedBox: return "oriented_box";
  }
  return "unknown";
}

}  // namespace ccd
