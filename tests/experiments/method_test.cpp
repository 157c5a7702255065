// Method names: BOUND/BROADPHASE[@SCHEDULER], each part resolved by its registry.
#include "../../experiments/method.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

namespace experiments_method_test {

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

TEST_CASE("a method is parsed once into its parts, and its parts give the name back", "[methods]") {
  for (const std::string name : {"aabb/sap", "capsule/grid:cell=2", "horn:4/sap", "horn:pieces=8/sap",
                                 "horn:4/grid@earliest", "capsule/sap@earliest:stale=0.5",
                                 "horn/grid@fixed:narrow_from_earliest=1"}) {
    INFO(name);
    const ccdlab::MethodSpec m = ccdlab::parse_method(name);
    CHECK(m.to_string() == name);
    const ccdlab::MethodSpec again = ccdlab::parse_method(m.to_string());
    CHECK(again == m);
    CHECK(ccdlab::options_json(again) == ccdlab::options_json(m));
    CHECK(m.fixed_step_name() == name.substr(0, name.find('@')));
    CHECK(m.bound_text + "/" + m.broad_phase_text == m.fixed_step_name());
    CHECK(m.scheduler_text == (m.scheduler_named ? name.substr(name.find('@') + 1) : std::string()));
  }
  const ccdlab::MethodSpec m = ccdlab::parse_method("horn:4/grid:cell=2@earliest:stale=0.5");
  CHECK(m.bound_text == "horn:4");
  CHECK(m.bound.info->name == "horn");
  CHECK(m.broad_phase_text == "grid:cell=2");
  CHECK(m.broad_phase.info->name == "grid");
  CHECK(m.scheduler_text == "earliest:stale=0.5");
  CHECK(m.scheduler.info->name == "earliest");
  // Every composed name round-trips.
  for (const std::string& n : ccdlab::all_method_names()) CHECK(ccdlab::parse_method(n).to_string() == n);
}

TEST_CASE("a bad method names the part that is wrong", "[methods]") {
  struct Case {
    std::string name, message;  // message: the start of the error
  };
  const Case cases[] = {
      {"capsule", "method 'capsule' is not of the form BOUND/BROADPHASE[@SCHEDULER]"},
      {"capsule/grid/sap", "method 'capsule/grid/sap' is not of the form BOUND/BROADPHASE[@SCHEDULER]"},
      {"capsul/grid", "unknown bound 'capsul'"},
      {"horn:0/grid", "bound 'horn:0': "},
      {"capsule/gird", "unknown broad phase 'gird'"},
      {"capsule/grid:cell=-1", "broad phase 'grid:cell=-1': "},
      {"capsule/grid@later", "unknown scheduler 'later'"},
      {"capsule/grid@earliest:stale=2", "scheduler 'earliest:stale=2': "},
      {"aabb/sap@earliest", "method 'aabb/sap@earliest': bound 'aabb' is an instant bound"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    try {
      ccdlab::parse_method(c.name);
      FAIL("no error");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).rfind(c.message, 0) == 0);
    }
  }
}

}  // namespace experiments_method_test
