// Method names: BOUND/BROADPHASE[@SCHEDULER], each part resolved by its registry.
#include "../../experiments/method.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

TEST_CASE("method names compose a bound, a broad phase and a scheduler", "[methods][scheduler]") {
  SECTION("no scheduler: fixed steps, and the options say nothing more than before") {
    const ccdlab::MethodSpec m = ccdlab::parse_method("horn:4/grid");
    CHECK_FALSE(m.scheduled());
    CHECK_FALSE(m.scheduler_named);
    CHECK_FALSE(ccdlab::options_json(m).contains("scheduler"));
  }
  SECTION("@earliest with options, recorded in the options") {
    const ccdlab::MethodSpec m = ccdlab::parse_method("capsule/sap@earliest:stale=0.5");
    CHECK(m.scheduled());
    CHECK(m.name == "capsule/sap@earliest:stale=0.5");
    CHECK(m.bound.info->name == "capsule");
    CHECK(m.broad_phase.info->name == "sap");
    const nlohmann::json o = ccdlab::options_json(m);
    CHECK(o["scheduler"]["name"] == "earliest");
    CHECK(o["scheduler"]["stale"] == 0.5);
    CHECK(o["scheduler"]["align"] == 1);
  }
  SECTION("@fixed:narrow_from_earliest=1 is a fixed-step method with the option recorded") {
    const ccdlab::MethodSpec m = ccdlab::parse_method("horn/grid@fixed:narrow_from_earliest=1");
    CHECK_FALSE(m.scheduled());
    CHECK(ccdlab::options_json(m)["scheduler"]["narrow_from_earliest"] == 1);
  }
  SECTION("refused: an instant bound under @earliest, unknown schedulers, bad options") {
    CHECK_THROWS_AS(ccdlab::parse_method("sphere/grid@earliest"), std::invalid_argument);
    CHECK_THROWS_AS(ccdlab::parse_method("aabb/sap@earliest"), std::invalid_argument);
    CHECK_THROWS_AS(ccdlab::parse_method("capsule/grid@later"), std::invalid_argument);
    CHECK_THROWS_AS(ccdlab::parse_method("capsule/grid@earliest:stale=2"), std::invalid_argument);
    CHECK_THROWS_AS(ccdlab::parse_method("capsule/grid@"), std::invalid_argument);
  }
  SECTION("every scheduled name parses and is a conservative space-time method") {
    const auto names = ccdlab::scheduled_method_names();
    // swept_aabb, capsule, horn, horn_sat, enclosing_sphere, obb_sat
    CHECK(names.size() == 6 * ccd::broad_phase_registry().size());
    for (const std::string& n : names) {
      const ccdlab::MethodSpec m = ccdlab::parse_method(n);
      CHECK(m.scheduled());
      CHECK(m.continuous());
    }
  }
}
