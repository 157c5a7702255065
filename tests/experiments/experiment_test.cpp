// Experiment files: timesteps given as dt and as frequencies, list_missed, and strict
// fields (unknown ones named with the nearest known one).
#include "../../experiments/experiment.hpp"

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>

namespace experiments_experiment_test {

using ccdlab::experiment_from_json;
using nlohmann::json;

namespace {

json minimal() {
  return json::parse(R"({"format": "ccdlab-experiment/1", "name": "t",
    "scene": {"generator": "gas", "bodies": 10, "seed": 1}, "dt": [0.1], "methods": ["aabb/brute"]})");
}

std::string error_of(const json& j) {
  try {
    experiment_from_json(j, "e.json");
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("hz gives timesteps as frequencies, joined with dt, sorted by dt", "[experiment]") {
  json j = minimal();
  j["dt"] = json::array({0.1, 0.0125});
  j["hz"] = json::array({60, 10, 240});
  const auto e = experiment_from_json(j, "e.json");
  // 1/10 == 0.1 exactly in double: one timestep, kept with its frequency as given.
  REQUIRE(e.dt == std::vector<double>{0.1, 1.0 / 60, 0.0125, 1.0 / 240});
  CHECK(e.hz == std::vector<double>{10, 60, 80, 240});
  CHECK(e.hz_given == std::vector<bool>{true, true, false, true});
  SECTION("the stored form reads back to the same timesteps") {
    const json stored = ccdlab::experiment_to_json(e);
    CHECK(stored["hz"] == json::array({10, 60, 240}));
    const auto again = experiment_from_json(stored, "e.json");
    CHECK(again.dt == e.dt);
    CHECK(again.hz == e.hz);
    CHECK(again.hz_given == e.hz_given);
  }
  SECTION("hz alone, as a range") {
    j.erase("dt");
    j["hz"] = {{"from", 30}, {"to", 240}, {"count", 4}};
    const auto r = experiment_from_json(j, "e.json");
    REQUIRE(r.hz.size() == 4);
    CHECK(r.hz[0] == 30);  // the ends exactly as written, the others on the log scale
    CHECK(r.hz[1] == Approx(60).epsilon(1e-14));
    CHECK(r.hz[2] == Approx(120).epsilon(1e-14));
    CHECK(r.hz[3] == 240);
    CHECK(r.dt.front() == 1.0 / 30);
    CHECK(r.hz_given == std::vector<bool>{true, true, true, true});
  }
  SECTION("bad frequencies name the field") {
    j["hz"] = json::array({60, -1});
    CHECK(error_of(j) == "e.json: hz[1]: must be a finite number > 0");
    j.erase("hz");
    j.erase("dt");
    CHECK(error_of(j) == R"(e.json: dt: missing required field (or give frequencies as "hz"))");
  }
}

TEST_CASE("list_missed is an experiment option, false by default", "[experiment]") {
  json j = minimal();
  CHECK_FALSE(experiment_from_json(j, "e.json").list_missed);
  j["list_missed"] = true;
  CHECK(experiment_from_json(j, "e.json").list_missed);
  j["list_missed"] = 1;
  CHECK(error_of(j) == "e.json: list_missed: must be true or false");
}

TEST_CASE("an unknown field in an experiment is an error with the nearest known name", "[experiment]") {
  json j = minimal();
  SECTION("top level") {
    j["method"] = json::array({"aabb/sap"});
    CHECK(error_of(j) == R"(e.json: method: unknown field (did you mean "methods"?))");
  }
  SECTION("a dt range") {
    j["dt"] = {{"from", 0.01}, {"to", 0.1}, {"cont", 3}};
    CHECK(error_of(j) == R"(e.json: dt.cont: unknown field (did you mean "count"?))");
  }
  SECTION("a generator parameter") {
    j["scene"]["bodys"] = 20;
    CHECK(error_of(j) == R"(e.json: scene.bodys: unknown field (did you mean "bodies"?))");
  }
  SECTION("an unknown generator") {
    j["scene"]["generator"] = "gass";
    CHECK(error_of(j).rfind(R"(e.json: scene.generator: unknown generator 'gass' (did you mean "gas"?))", 0) == 0);
  }
  SECTION("description and comment are allowed; comment is not a generator parameter") {
    j["description"] = "what this measures";
    j["comment"] = "a note";
    j["scene"]["comment"] = "a note on the scene";
    const auto e = experiment_from_json(j, "e.json");
    CHECK_FALSE(e.scene_generator.contains("comment"));
  }
}

}  // namespace experiments_experiment_test
