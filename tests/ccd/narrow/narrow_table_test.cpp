// The narrow-phase table and its sphere x sphere entry, on a pair worked out by hand; its
// polygon column.
#include <ccd/motion/state_cursor.hpp>
#include <ccd/narrow/body_polygon_narrow.hpp>
#include <ccd/narrow/narrow_table.hpp>
#include <ccd/narrow/sphere_polygon_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ccd_narrow_narrow_table_test {

using ccd::Vec3;

namespace {

// Two spheres of radius 0.5 approach head-on at relative speed 2 from 10 apart (dyadic
// data): they touch at t = 4.5, their centres coincide at t = 5, they part at t = 5.5.
ccd::Scene head_on() {
  ccd::Scene s;
  s.horizon = 10.0;
  s.bodies.push_back({0.5, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), {}});
  s.bodies.push_back({0.5, Vec3(10, 0, 0), Vec3(-1, 0, 0), Vec3::Zero(), {}});
  return s;
}

ccd::ContactResult step_query(const ccd::Trajectories& m, double t0, double t1) {
  const ccd::RigidMotion motion(m);
  return ccd::sphere_sphere_narrow({&motion, {}, {}, t0, t1, false}, 0, 1);
}

ccd::ContactResult sample_at(const ccd::Trajectories& m, double t) {
  std::vector<ccd::BodyState> start;
  ccd::StateCursor cursor(m);
  cursor.evaluate(t, start);
  const ccd::RigidMotion motion(m);
  return ccd::sphere_sphere_narrow({&motion, start, cursor.pieces(), t, t, true}, 0, 1);
}

}  // namespace

TEST_CASE("the default narrow table binds sphere x sphere to the exact solver", "[narrow]") {
  const ccd::NarrowTable& table = ccd::narrow_table();
  REQUIRE(table.contains(ccd::ShapeKind::Sphere, ccd::ShapeKind::Sphere));
  const ccd::NarrowEntry e = table.find(ccd::ShapeKind::Sphere, ccd::ShapeKind::Sphere);
  CHECK(e.fn == &ccd::sphere_sphere_narrow);
  CHECK_FALSE(e.swapped);
  // An empty table has no entry and says which pair is missing.
  const ccd::NarrowTable empty;
  CHECK_FALSE(empty.contains(ccd::ShapeKind::Sphere, ccd::ShapeKind::Sphere));
  CHECK_THROWS_WITH(empty.find(ccd::ShapeKind::Sphere, ccd::ShapeKind::Sphere),
                    Catch::Contains("no narrow phase for sphere x sphere"));
}

TEST_CASE("sphere x sphere step queries: first contact, its accuracy and signed distance", "[narrow]") {
  const ccd::Scene s = head_on();
  const ccd::Trajectories m(s);
  SECTION("a step that contains the first contact: Hit at 4.5, exact, touching") {
    const ccd::ContactResult r = step_query(m, 4.0, 5.0);
    CHECK(r.status == ccd::QueryStatus::Hit);
    CHECK(r.found());
    CHECK(r.toi == Approx(4.5).margin(1e-12));
    CHECK(r.toi_error == 0.0);
    CHECK(std::abs(r.signed_distance) <= 1e-12);
  }
  SECTION("a step inside the contact: Overlapping at its start, 1 deep at t = 5") {
    const ccd::ContactResult r = step_query(m, 5.0, 5.25);
    CHECK(r.status == ccd::QueryStatus::Overlapping);
    CHECK(r.toi == 5.0);
    CHECK(r.signed_distance == -1.0);  // coincident centres: depth r_a + r_b
  }
  SECTION("a step before the contact: Miss, toi +inf, no distance") {
    const ccd::ContactResult r = step_query(m, 0.0, 4.25);
    CHECK(r.status == ccd::QueryStatus::Miss);
    CHECK_FALSE(r.found());
    CHECK(r.toi == std::numeric_limits<double>::infinity());
    CHECK(std::isnan(r.signed_distance));
  }
  SECTION("the signed distance helper at any time") {
    CHECK(ccd::sphere_signed_distance(m, 0, 1, 0.0) == 9.0);   // 10 apart, radii 0.5 + 0.5
    CHECK(ccd::sphere_signed_distance(m, 1, 0, 5.25) == -0.5);  // symmetric in the pair
  }
}

TEST_CASE("sphere x sphere sample tests use the truth's definition of touching", "[narrow]") {
  const ccd::Scene s = head_on();
  const ccd::Trajectories m(s);
  // t = 4.5 and 5.5: exactly touching (dyadic: the distance is exactly 1); counts.
  for (double t : {4.5, 5.0, 5.5}) {
    CAPTURE(t);
    const ccd::ContactResult r = sample_at(m, t);
    CHECK(r.status == ccd::QueryStatus::Overlapping);
    CHECK(r.toi == t);
    CHECK(r.signed_distance == std::abs(10.0 - 2.0 * t) - 1.0);
  }
  for (double t : {0.0, 4.25, 5.75}) {
    CAPTURE(t);
    CHECK(sample_at(m, t).status == ccd::QueryStatus::Miss);
  }
  // Without the cursor's piece indices the answer is the same.
  std::vector<ccd::BodyState> start;
  ccd::StateCursor(m).evaluate(4.5, start);
  const ccd::RigidMotion motion(m);
  CHECK(ccd::sphere_sphere_narrow({&motion, start, {}, 4.5, 4.5, true}, 0, 1).found());
}

TEST_CASE("the narrow table's polygon column: spheres exact, other shapes by conservative advancement",
          "[narrow][scenery]") {
  const ccd::NarrowTable& table = ccd::narrow_table();
  REQUIRE(table.contains_polygon(ccd::ShapeKind::Sphere));
  CHECK(table.find_polygon(ccd::ShapeKind::Sphere) == &ccd::sphere_polygon_narrow);
  for (std::size_t k = 0; k < ccd::kShapeKinds; ++k) {
    const auto kind = static_cast<ccd::ShapeKind>(k);
    INFO(ccd::to_string(kind));
    if (kind != ccd::ShapeKind::Sphere) CHECK(table.find_polygon(kind) == &ccd::polygon_advancement);
  }
  // An empty table has no polygon entry and says which one is missing; add_polygon fills
  // one kind only and replaces an existing entry.
  ccd::NarrowTable t;
  CHECK_FALSE(t.contains_polygon(ccd::ShapeKind::Box));
  CHECK_THROWS_WITH(t.find_polygon(ccd::ShapeKind::Box), Catch::Contains("no narrow phase for box x polygon"));
  t.add_polygon(ccd::ShapeKind::Box, &ccd::polygon_advancement);
  CHECK(t.find_polygon(ccd::ShapeKind::Box) == &ccd::polygon_advancement);
  CHECK_FALSE(t.contains_polygon(ccd::ShapeKind::Sphere));
  t.add_polygon(ccd::ShapeKind::Box, &ccd::sphere_polygon_narrow);
  CHECK(t.find_polygon(ccd::ShapeKind::Box) == &ccd::sphere_polygon_narrow);
}

}  // namespace ccd_narrow_narrow_table_test
