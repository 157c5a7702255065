#pragma once
// Mass properties of a shape (docs/rigid_bodies.md, "Free spin"): mass, centre of mass and
// the inertia tensor about the centre of mass, in the body frame, for a uniform density.
//
//  - sphere (radius r):      m = rho 4/3 pi r^3, I = 2/5 m r^2 on every axis;
//  - box (half extents h):   m = rho 8 hx hy hz, I_xx = m (hy^2 + hz^2) / 3 (and cyclic);
//  - capsule (axis x, half length h, radius r): a cylinder of length 2h (mass m_c) and two
//    half balls (together m_s): I_xx = m_c r^2 / 2 + m_s 2 r^2 / 5,
//    I_yy = I_zz = m_c (r^2 / 4 + h^2 / 3) + m_s (2 r^2 / 5 + h^2 + 3 h r / 4);
//  - hull: the polyhedron's volume integrals (the divergence theorem over its faces, after
//    Mirtich 1996), as a sum of tetrahedra from an inner point to the triangulated faces:
//    a tetrahedron with corners v0..v3 and volume V has
//    integral of x x^T = V / 20 (sum v_i v_i^T + (sum v_i)(sum v_i)^T).
// Units: metres, kg/m^3, kg, kg m^2. The hull's faces are its convex hull's
// (ccd/shape/convex_hull.hpp, points x faces time: a scene bounds the point count).
#include <ccd/geometry/vec3.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Core>

namespace ccd {

struct MassProperties {
  double volume = 0.0;                        ///< m^3
  double mass = 0.0;                          ///< kg
  Vec3 centre{Vec3::Zero()};                  ///< centre of mass, body frame
  Eigen::Matrix3d inertia{Eigen::Matrix3d::Zero()};  ///< about the centre, body frame
};

/// The default density of a shaped body without `mass` or `density` (kg/m^3, water).
inline constexpr double kDefaultDensity = 1000.0;

/// Mass properties of `shape` at uniform `density` (> 0).
MassProperties mass_properties(const Shape& shape, double density);
/// A plain sphere of `radius`.
MassProperties sphere_mass_properties(double radius, double density);

/// Principal moments (ascending) and axes (columns, body frame, a proper rotation) of a
/// symmetric inertia tensor; a diagonal tensor keeps the body axes (permuted, exactly).
struct PrincipalInertia {
  Vec3 moments{Vec3::Ones()};
  Eigen::Matrix3d axes{Eigen::Matrix3d::Identity()};
};
PrincipalInertia principal_inertia(const Eigen::Matrix3d& inertia);

}  // namespace ccd
