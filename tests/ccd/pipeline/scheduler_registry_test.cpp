#include <ccd/pipeline/scheduler_registry.hpp>

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

TEST_CASE("parse_scheduler resolves names and options", "[pipeline][scheduler][registry]") {
  const ccd::SchedulerSpec fixed = ccd::parse_scheduler("fixed");
  CHECK_FALSE(fixed.earliest());
  CHECK(fixed.options.integer("narrow_from_earliest") == 0);
  CHECK(fixed.options.integer("kinematic") == 0);  // the kinematic principle is opt-in
  CHECK(ccd::parse_scheduler("fixed:kinematic=1").options.integer("kinematic") == 1);
  CHECK_THROWS_AS(ccd::parse_scheduler("fixed:kinematic=2"), std::invalid_argument);
  CHECK(ccd::default_scheduler().info == fixed.info);
  const ccd::SchedulerSpec e = ccd::parse_scheduler("earliest");
  CHECK(e.earliest());
  CHECK(e.options.number("stale") == 0.25);
  CHECK(e.options.integer("align") == 1);
  CHECK(ccd::parse_scheduler("earliest:0.5").options.number("stale") == 0.5);  // first option
  CHECK(ccd::parse_scheduler("earliest:stale=1,align=0").options.integer("align") == 0);
  CHECK(ccd::parse_scheduler("fixed:narrow_from_earliest=1").options.integer("narrow_from_earliest") == 1);
  CHECK(e.options.integer("recheck") == 0);  // speed re-checks are opt-in
  CHECK(e.options.number("chunk") == 2.0);
  const ccd::SchedulerSpec r = ccd::parse_scheduler("earliest:recheck=1,chunk=0");
  CHECK(r.options.integer("recheck") == 1);
  CHECK(r.options.number("chunk") == 0.0);
  SECTION("bad names and values name the part and list the valid ones") {
    try {
      ccd::parse_scheduler("hubbard");
      FAIL("accepted");
    } catch (const std::invalid_argument& err) {
      CHECK(std::string(err.what()).find("valid schedulers: fixed, earliest") != std::string::npos);
    }
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:stale=0"), std::invalid_argument);  // (0, 1]
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:stale=1.5"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:align=2"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:recheck=2"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:chunk=-1"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("fixed:stale=0.5"), std::invalid_argument);
  }
}
