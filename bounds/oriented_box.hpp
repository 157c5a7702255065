#pragma once
// Oriented box: a centre, orthonormal axes (the columns of `axes`) and half-widths along
// them. The building block of `obb` and `obb_sat` (docs/bounds.md).
//
// oriented_boxes_overlap: the separating-axis test of two static oriented boxes
// (Gottschalk; ccd-math §5): 3 + 3 face normals and 9 edge crosses. Disjoint only when one
// of the 15 axes separates them. Conservative tolerances, as for the moving boxes of
// bounds/oriented_trapezoid.hpp:
// - |R_ij| + kSatParallelEpsilon (1e-9) on every entry of the relative rotation: an
//   edge-cross axis of two (near-)parallel edges is a near-zero vector whose test is all
//   rounding; the epsilon keeps its radius above the projected distance (Ericson's fix);
// - every radius is widened by 16 ulps of (|T|_1 + all half-widths), the size of the
//   rounding errors of the projections.
// So boxes that touch or overlap are never reported disjoint.
#include <ccd/geometry/aabb.hpp>
#include <ccd/geometry/vec3.hpp>

#include <Eigen/Core>

namespace ccd {

struct OrientedBox {
  Vec3 centre{Vec3::Zero()};
  Eigen::Matrix3d axes{Eigen::Matrix3d::Identity()};  ///< orthonormal columns
  Vec3 half{Vec3::Zero()};                            ///< half-widths along the columns

  /// The world AABB that encloses the box: centre -/+ |axes| half.
  Aabb hull() const {
    const Vec3 e = axes.cwiseAbs() * half;
    return {centre - e, centre + e};
  }
};

/// See the header comment.
bool oriented_boxes_overlap(const OrientedBox& a, const OrientedBox& b);

}  // namespace ccd
