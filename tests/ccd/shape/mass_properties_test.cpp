// Mass properties (ccd/shape/mass_properties.hpp): the closed forms against hand values,
// the hull's volume integrals against the box and a tetrahedron, principal axes.
#include <ccd/shape/mass_properties.hpp>

#include <catch2/catch.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace ccd_shape_mass_properties_test {

using ccd::Vec3;
using Mat3 = Eigen::Matrix3d;

TEST_CASE("mass properties of the closed-form shapes", "[shape][mass]") {
  const double pi = std::numbers::pi;
  SECTION("sphere: 2/5 m r^2") {
    const ccd::MassProperties m = ccd::mass_properties(ccd::make_sphere_shape(0.5), 1000.0);
    CHECK(m.mass == Approx(1000.0 * 4.0 / 3.0 * pi * 0.125).epsilon(1e-15));
    CHECK(m.inertia(0, 0) == Approx(0.4 * m.mass * 0.25).epsilon(1e-15));
    CHECK(m.inertia(1, 1) == m.inertia(0, 0));
    CHECK(m.inertia(0, 1) == 0.0);
  }
  SECTION("box 2 x 1 x 0.5 of density 2: m = 2, I = m (b^2 + c^2) / 12 on full widths") {
    const ccd::MassProperties m = ccd::mass_properties(ccd::make_box_shape(Vec3(1, 0.5, 0.25)), 2.0);
    CHECK(m.mass == 2.0);
    CHECK(m.inertia(0, 0) == Approx(2.0 * (1.0 + 0.25) / 12.0).epsilon(1e-15));
    CHECK(m.inertia(1, 1) == Approx(2.0 * (4.0 + 0.25) / 12.0).epsilon(1e-15));
    CHECK(m.inertia(2, 2) == Approx(2.0 * (4.0 + 1.0) / 12.0).epsilon(1e-15));
  }
  SECTION("capsule: a cylinder and two half balls") {
    // h = 1, r = 0.5, density 1: cylinder pi r^2 2h = pi/2, ball 4/3 pi r^3 = pi/6.
    const ccd::MassProperties m = ccd::mass_properties(ccd::make_capsule_shape(1.0, 0.5), 1.0);
    const double mc = pi / 2, ms = pi / 6;
    CHECK(m.mass == Approx(mc + ms).epsilon(1e-15));
    CHECK(m.inertia(0, 0) == Approx(mc * 0.25 / 2 + ms * 0.4 * 0.25).epsilon(1e-15));
    // Perpendicular: cylinder m (r^2/4 + L^2/12) with L = 2; each half ball about its own
    // centre of mass (3r/8 from the flat face), moved out to h + 3r/8.
    const double half = ms / 2, dcm = 3.0 * 0.5 / 8.0;
    const double own = 0.4 * half * 0.25 - half * dcm * dcm;
    const double across = mc * (0.25 / 4 + 4.0 / 12) + 2.0 * (own + half * (1.0 + dcm) * (1.0 + dcm));
    CHECK(m.inertia(1, 1) == Approx(across).epsilon(1e-14));
    CHECK(m.inertia(2, 2) == m.inertia(1, 1));
    // A capsule shrinking to a ball of radius r: 2/5 m r^2 on every axis.
    const ccd::MassProperties b = ccd::mass_properties(ccd::make_capsule_shape(1e-12, 0.5), 1.0);
    CHECK(b.inertia(1, 1) == Approx(0.4 * b.mass * 0.25).epsilon(1e-9));
  }
}

TEST_CASE("hull mass properties by the volume integrals", "[shape][mass]") {
  SECTION("a box given as a hull equals the box") {
    const ccd::Shape box = ccd::make_box_shape(Vec3(0.75, 0.5, 0.125));
    const ccd::MassProperties a = ccd::mass_properties(box, 3.0);
    const ccd::MassProperties b = ccd::mass_properties(ccd::make_hull_shape(box.points), 3.0);
    CHECK(b.volume == Approx(a.volume).epsilon(1e-14));
    CHECK(b.centre.norm() <= 1e-15);
    CHECK((b.inertia - a.inertia).norm() <= 1e-14 * a.inertia.norm());
  }
  SECTION("a box with points inside and on its faces, far from the origin") {
    ccd::Shape box = ccd::make_box_shape(Vec3(1, 2, 4));
    std::vector<Vec3> pts = box.points;
    pts.push_back(Vec3(0, 0, 4));      // on a face
    pts.push_back(Vec3(0.5, -2, 1));   // on a face
    pts.push_back(Vec3(1, 2, 0));      // on an edge
    pts.push_back(Vec3(0.1, 0.2, 0.3));  // inside
    const Vec3 shift(1024, -2048, 512);
    for (Vec3& p : pts) p += shift;
    const ccd::MassProperties a = ccd::mass_properties(box, 1.0);
    const ccd::MassProperties b = ccd::mass_properties(ccd::make_hull_shape(pts), 1.0);
    CHECK(b.volume == Approx(64.0).epsilon(1e-12));
    CHECK((b.centre - shift).norm() <= 1e-9);
    CHECK((b.inertia - a.inertia).norm() <= 1e-9 * a.inertia.norm());
  }
  SECTION("the unit corner tetrahedron") {
    // Volume 1/6, centre (1/4, 1/4, 1/4); about the origin integral x^2 = 1/60 and
    // integral x y = 1/120, so about the centre I_xx = 2 (1/60 - 1/6 / 16) = 1/80 and
    // I_xy = -(1/120 - 1/6 / 16) = 1/480.
    const ccd::MassProperties m =
        ccd::mass_properties(ccd::make_hull_shape({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), 1.0);
    CHECK(m.volume == Approx(1.0 / 6).epsilon(1e-14));
    CHECK((m.centre - Vec3::Constant(0.25)).norm() <= 1e-15);
    CHECK(m.inertia(0, 0) == Approx(1.0 / 80).epsilon(1e-13));
    CHECK(m.inertia(1, 1) == Approx(1.0 / 80).epsilon(1e-13));
    CHECK(m.inertia(0, 1) == Approx(1.0 / 480).epsilon(1e-12));
    CHECK(m.inertia(1, 2) == Approx(1.0 / 480).epsilon(1e-12));
  }
}

TEST_CASE("principal inertia: ascending moments, proper axes, diagonal tensors exact", "[shape][mass]") {
  const ccd::PrincipalInertia d = ccd::principal_inertia(Vec3(3, 1, 2).asDiagonal());
  CHECK(d.moments == Vec3(1, 2, 3));
  CHECK(d.axes.determinant() == 1.0);
  CHECK(d.axes.col(0).cwiseAbs() == Vec3::UnitY());
  CHECK(d.axes.col(2).cwiseAbs() == Vec3::UnitX());
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  const Mat3 I = R * Vec3(0.5, 1.5, 2.5).asDiagonal() * R.transpose();
  const ccd::PrincipalInertia p = ccd::principal_inertia(I);
  CHECK((p.moments - Vec3(0.5, 1.5, 2.5)).norm() <= 1e-14);
  CHECK(p.axes.determinant() == Approx(1.0));
  CHECK((p.axes * p.moments.asDiagonal() * p.axes.transpose() - I).norm() <= 1e-14);
}

}  // namespace ccd_shape_mass_properties_test
