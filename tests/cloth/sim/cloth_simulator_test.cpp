#include <cloth/sim/cloth_simulator.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace cloth_sim_cloth_simulator_test {

using ccd::Vec3;
using ccd::cloth::builtin_cloth_scene;
using ccd::cloth::ClothScene;
using ccd::cloth::ClothSimulator;
using ccd::cloth::make_grid_mesh;
using ccd::cloth::SpringKind;

namespace {

ClothScene small_sheet(int nx, int ny) {
  ClothScene s;
  s.nx = nx;
  s.ny = ny;
  s.du = Vec3(0.125, 0, 0);
  s.dv = Vec3(0, 0, 0.125);
  s.particle_mass = 0.01;
  s.structural = {200, 0.2};
  s.shear = {20, 0.02};
  s.bend = {2, 0.002};
  s.step = 0.01;
  return s;
}

}  // namespace

TEST_CASE("grid mesh: triangles, edges and springs of an nx x ny grid", "[cloth][sim]") {
  const auto m = make_grid_mesh(small_sheet(4, 3));
  std::size_t structural = 0, shear = 0, bend = 0;
  for (const auto& s : m.springs) {
    structural += s.kind == SpringKind::Structural;
    shear += s.kind == SpringKind::Shear;
    bend += s.kind == SpringKind::Bend;
  }
  CHECK(structural == 4 * 2 + 3 * 3);  // nx (ny - 1) + ny (nx - 1)
  CHECK(shear == 2 * 3 * 2);           // 2 (nx - 1)(ny - 1)
  CHECK(bend == 4 * 1 + 3 * 2);        // nx (ny - 2) + ny (nx - 2)
  CHECK(m.triangles.size() == 12);     // 2 (nx - 1)(ny - 1)
  CHECK(m.edges.size() == 17 + 6);     // structural edges + one diagonal per quad
  CHECK(m.springs[0].rest == 0.125);
}

TEST_CASE("implicit Euler: a free sheet falls exactly as a rigid body", "[cloth][sim]") {
  // Springs at rest exert nothing and a uniform velocity is in the null space of the
  // stiffness and damping Jacobians, so dv = h g: v_k = k h g, x_k = x_0 + h^2 g k(k+1)/2.
  ClothScene s = small_sheet(5, 5);
  s.gravity = Vec3(0, -9.81, 0);
  ClothSimulator sim(s);
  const Vec3 x0 = sim.positions()[7];
  for (int k = 0; k < 20; ++k) sim.step();
  const double expect = -9.81 * 0.01 * 0.01 * 20 * 21 / 2;
  for (const Vec3& v : sim.velocities()) CHECK(v.y() == Approx(-9.81 * 0.2).epsilon(1e-9));
  CHECK(sim.positions()[7].y() - x0.y() == Approx(expect).epsilon(1e-9));
  CHECK(sim.positions()[7].x() == x0.x());
}

TEST_CASE("implicit Euler: a sheet hanging from two corners comes to rest", "[cloth][sim]") {
  ClothScene s = small_sheet(6, 6);
  s.gravity = Vec3(0, -9.81, 0);
  s.pinned = {s.particle(0, 0), s.particle(5, 0)};
  s.air_damping = 0.02;  // springs do not damp the swing of the whole sheet; the air does
  ClothSimulator sim(s);
  const Vec3 pin0 = sim.positions()[s.pinned[0]];
  for (int k = 0; k < 600; ++k) sim.step();
  CHECK(sim.positions()[s.pinned[0]] == pin0);
  double speed = 0, lowest = 0;
  for (std::size_t p = 0; p < sim.positions().size(); ++p) {
    speed = std::max(speed, sim.velocities()[p].norm());
    lowest = std::min(lowest, sim.positions()[p].y());
    CHECK(sim.positions()[p].y() <= 1e-12);  // nothing rises above the pins
  }
  CHECK(speed < 1e-3);
  CHECK(lowest < -0.5);  // it hangs: the free corners drop by about the sheet's size
  CHECK(lowest > -1.5);  // springs hold it: stretch stays bounded
}

TEST_CASE("implicit Euler is stable with stiff springs and a large step", "[cloth][sim]") {
  ClothScene s = small_sheet(6, 6);
  s.structural = {1e6, 10};
  s.step = 0.05;
  s.gravity = Vec3(0, -9.81, 0);
  s.pinned = {s.particle(0, 0)};
  ClothSimulator sim(s);
  for (int k = 0; k < 100; ++k) sim.step();
  for (const Vec3& x : sim.positions()) {
    CHECK(std::isfinite(x.norm()));
    CHECK(x.norm() < 3.0);
  }
}

TEST_CASE("cloth obstacles and prescribed motion", "[cloth][sim]") {
  SECTION("drape: no particle ends inside the sphere or the floor, and the cloth rests on the sphere") {
    ClothScene s = builtin_cloth_scene("drape", 12);
    s.steps = 150;
    ClothSimulator sim(s);
    double closest = 1e9;
    for (int k = 0; k < s.steps; ++k) {
      sim.step();
      for (const Vec3& x : sim.positions()) {
        REQUIRE((x - s.spheres[0].center).norm() >= s.spheres[0].radius + s.thickness - 1e-12);
        REQUIRE(x.y() >= *s.floor + s.thickness - 1e-12);
      }
    }
    for (const Vec3& x : sim.positions()) closest = std::min(closest, (x - s.spheres[0].center).norm());
    CHECK(closest == Approx(s.spheres[0].radius + s.thickness).epsilon(1e-9));
  }
  SECTION("twist: spun particles are exactly on their rotation, pinned ones still") {
    ClothScene s = builtin_cloth_scene("twist", 8);
    ClothSimulator sim(s);
    const auto x0 = sim.positions();
    for (int k = 0; k < 100; ++k) sim.step();  // 0.5 s at pi rad/s: a quarter turn about x
    for (std::uint32_t p : s.spin->particles) {
      const Vec3 r0 = x0[p] - s.spin->center, r1 = sim.positions()[p] - s.spin->center;
      CHECK(r1.x() == Approx(r0.x()).margin(1e-12));
      CHECK(r1.y() == Approx(-r0.z()).margin(1e-12));  // (y, z) -> (-z, y): a quarter turn about +x
      CHECK(r1.z() == Approx(r0.y()).margin(1e-12));
    }
    for (std::uint32_t p : s.pinned) CHECK(sim.positions()[p] == x0[p]);
  }
}

}  // namespace cloth_sim_cloth_simulator_test
