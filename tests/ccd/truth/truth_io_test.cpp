#include <ccd/scene/input_error.hpp>
#include <ccd/truth/truth_io.hpp>

#include <catch2/catch.hpp>

using ccd::ContactEvent;
using ccd::TruthFile;
using nlohmann::json;

namespace {

std::string error_of(const json& j) {
  try {
    ccd::truth_from_json(j, "t.json");
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "";
}

TruthFile sample() {
  return {2.0, {{0, 3, 0.0, 0.1 + 0.2}, {1, 2, 1.0 / 3.0, 1.0 / 3.0}, {0, 1, 1.5, 2.0}}};
}

}  // namespace

TEST_CASE("truth files round-trip bit for bit", "[truth][io]") {
  const TruthFile t = sample();
  const TruthFile back = ccd::truth_from_json(json::parse(ccd::truth_to_text(t)), "t.json");
  CHECK(back.horizon == t.horizon);
  CHECK(back.events == t.events);
  const TruthFile back2 = ccd::truth_from_json(ccd::truth_to_json(t), "t.json");
  CHECK(back2.events == t.events);
  const TruthFile empty{1.0, {}};
  CHECK(ccd::truth_from_json(json::parse(ccd::truth_to_text(empty)), "t.json").events.empty());
}

TEST_CASE("bad truth files name the file and the field", "[truth][io]") {
  json j = ccd::truth_to_json(sample());
  SECTION("wrong format") {
    j["format"] = "ccdlab-truth/2";
    CHECK(error_of(j) == "t.json: format: must be \"ccdlab-truth/1\"");
  }
  SECTION("missing horizon") {
    j.erase("horizon");
    CHECK(error_of(j) == "t.json: horizon: missing required field");
  }
  SECTION("horizon <= 0") {
    j["horizon"] = 0.0;
    CHECK(error_of(j) == "t.json: horizon: must be > 0");
  }
  SECTION("missing exit") {
    j["events"][1].erase("exit");
    CHECK(error_of(j) == "t.json: events[1].exit: missing required field");
  }
  SECTION("negative body index") {
    j["events"][2]["a"] = -1;
    CHECK(error_of(j) == "t.json: events[2].a: must be a non-negative integer");
  }
  SECTION("a >= b") {
    j["events"][0]["a"] = 3;
    CHECK(error_of(j) == "t.json: events[0].b: must be greater than a");
  }
  SECTION("exit before enter") {
    j["events"][2]["exit"] = 1.0;
    CHECK(error_of(j) == "t.json: events[2].exit: must lie in [enter, horizon]");
  }
  SECTION("enter past the horizon") {
    j["events"][2]["enter"] = 2.5;
    CHECK(error_of(j) == "t.json: events[2].enter: must lie in [0, horizon]");
  }
  SECTION("out of order") {
    std::swap(j["events"][0], j["events"][2]);
    CHECK(error_of(j) == "t.json: events[1]: events must be sorted by (enter, a, b) without duplicates");
  }
  SECTION("not a number") {
    j["events"][0]["enter"] = "soon";
    CHECK(error_of(j) == "t.json: events[0].enter: must be a number");
  }
}
