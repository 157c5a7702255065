#include <ccd/io/input_error.hpp>
#include <ccd/truth/truth_io.hpp>

#include <catch2/catch.hpp>

namespace ccd_truth_truth_io_test {

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

const std::string kDigest(64, 'a');

TruthFile sample() {
  TruthFile t;
  t.horizon = 2.0;
  t.events = {{0, 3, 0.0, 0.1 + 0.2}, {1, 2, 1.0 / 3.0, 1.0 / 3.0}, {0, 1, 1.5, 2.0}};
  t.scene_sha256 = kDigest;
  return t;
}

}  // namespace

TEST_CASE("truth files round-trip bit for bit", "[truth][io]") {
  const TruthFile t = sample();
  const TruthFile back = ccd::truth_from_json(json::parse(ccd::truth_to_text(t)), "t.json");
  CHECK(back.horizon == t.horizon);
  CHECK(back.events == t.events);
  CHECK(back.scene_sha256 == kDigest);
  CHECK(back.version == 2);
  CHECK(back.errors.empty());
  const TruthFile back2 = ccd::truth_from_json(ccd::truth_to_json(t), "t.json");
  CHECK(back2.events == t.events);
  TruthFile empty;
  empty.horizon = 1.0;
  empty.scene_sha256 = kDigest;
  CHECK(ccd::truth_from_json(json::parse(ccd::truth_to_text(empty)), "t.json").events.empty());
}

TEST_CASE("truth files carry optional per-event errors, exact events write none", "[truth][io]") {
  TruthFile t = sample();
  // An exact truth writes the four fields per event, nothing else.
  CHECK(ccd::truth_to_text(t).find("error") == std::string::npos);
  t.errors = {{0.0, 0.0, false}, {1e-9, 2e-9, true}, {0.0, 0.5e-12, false}};
  const TruthFile back = ccd::truth_from_json(json::parse(ccd::truth_to_text(t)), "t.json");
  CHECK(back.events == t.events);
  CHECK(back.errors == t.errors);
  const json j = ccd::truth_to_json(t);
  CHECK_FALSE(j["events"][0].contains("enter_error"));
  CHECK(j["events"][1]["grazing"] == true);
  CHECK_FALSE(j["events"][2].contains("enter_error"));
  CHECK(j["events"][2]["exit_error"] == 0.5e-12);
}

TEST_CASE("version 1 truth files stay readable", "[truth][io]") {
  json j = ccd::truth_to_json(sample());
  j["format"] = "ccdlab-truth/1";
  j.erase("scene_sha256");
  j["events"][0]["enter_error"] = -5;  // not a version 1 field: ignored
  const TruthFile t = ccd::truth_from_json(j, "t.json");
  CHECK(t.version == 1);
  CHECK(t.scene_sha256.empty());
  CHECK(t.events == sample().events);
  CHECK(t.errors.empty());
}

TEST_CASE("a truth without a scene digest is written as version 1 and reads back", "[truth][io]") {
  // Found by fuzz_truth: a version 1 file read and written again came out as version 2
  // with "scene_sha256": "", which the reader (rightly) refuses.
  TruthFile t = sample();
  t.scene_sha256.clear();
  const std::string text = ccd::truth_to_text(t);
  CHECK(text.find("ccdlab-truth/1") != std::string::npos);
  CHECK(text.find("scene_sha256") == std::string::npos);
  const TruthFile again = ccd::truth_from_json(json::parse(text), "t.json");
  CHECK(again.version == 1);
  CHECK(again.events == t.events);
}

TEST_CASE("bad truth files name the file and the field", "[truth][io]") {
  json j = ccd::truth_to_json(sample());
  SECTION("wrong format") {
    j["format"] = "ccdlab-truth/3";
    CHECK(error_of(j) == "t.json: format: must be \"ccdlab-truth/2\" or \"ccdlab-truth/1\"");
  }
  SECTION("missing or malformed digest") {
    j.erase("scene_sha256");
    CHECK(error_of(j) == "t.json: scene_sha256: missing required field");
    j["scene_sha256"] = std::string(64, 'A');
    CHECK(error_of(j) == "t.json: scene_sha256: must be 64 lowercase hexadecimal digits");
  }
  SECTION("negative error, non-boolean grazing") {
    j["events"][1]["exit_error"] = -1e-9;
    CHECK(error_of(j) == "t.json: events[1].exit_error: must be >= 0");
    j["events"][1]["exit_error"] = 1e-9;
    j["events"][2]["grazing"] = 1;
    CHECK(error_of(j) == "t.json: events[2].grazing: must be true or false");
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

TEST_CASE("truth files carry static events only for scenes with scenery", "[truth][io][scenery]") {
  TruthFile t = sample();
  // No scenery: no static_events field at all (files of sphere scenes are unchanged).
  CHECK(ccd::truth_to_text(t).find("static_events") == std::string::npos);
  CHECK_FALSE(ccd::truth_to_json(t).contains("static_events"));
  // Scenery without contacts: an empty list.
  t.has_scenery = true;
  CHECK(ccd::truth_to_text(t).find("\"static_events\": []") != std::string::npos);
  t.static_events = {{2, 0, 0.0, 0.1 + 0.2}, {0, 5, 1.0 / 3.0, 1.0 / 3.0}, {1, 5, 1.0 / 3.0, 2.0}};
  const TruthFile back = ccd::truth_from_json(json::parse(ccd::truth_to_text(t)), "t.json");
  CHECK(back.has_scenery);
  CHECK(back.static_events == t.static_events);
  CHECK(back.events == t.events);
  const TruthFile back2 = ccd::truth_from_json(ccd::truth_to_json(t), "t.json");
  CHECK(back2.static_events == t.static_events);

  json j = ccd::truth_to_json(t);
  j["static_events"][1]["polygon"] = -1;
  CHECK(error_of(j).find("static_events[1].polygon") != std::string::npos);
  j = ccd::truth_to_json(t);
  j["static_events"][2]["exit"] = 3.0;
  CHECK(error_of(j).find("static_events[2].exit") != std::string::npos);
  j = ccd::truth_to_json(t);
  std::swap(j["static_events"][1], j["static_events"][2]);
  CHECK(error_of(j).find("static_events[2]") != std::string::npos);
  j = ccd::truth_to_json(t);
  j["static_events"] = 3;
  CHECK(error_of(j).find("static_events") != std::string::npos);
}

TEST_CASE("static events of rigid bodies carry their certified errors", "[truth][io][scenery][rigid]") {
  TruthFile t = sample();
  t.has_scenery = true;
  t.static_events = {{2, 0, 0.0, 0.1 + 0.2}, {0, 5, 1.0 / 3.0, 1.0 / 3.0}, {1, 5, 1.0 / 3.0, 2.0}};
  // All exact (spheres): no error field is written.
  t.static_errors = {{}, {}, {}};
  CHECK(ccd::truth_to_text(t).find("error") == std::string::npos);
  t.static_errors = {{0.0, 0.125, false}, {0.25, 0.25, true}, {}};
  const std::string text = ccd::truth_to_text(t);
  const TruthFile back = ccd::truth_from_json(json::parse(text), "t.json");
  CHECK(back.static_events == t.static_events);
  CHECK(back.static_errors == t.static_errors);
  CHECK(back.errors.empty());  // the body-body events stay exact
  const TruthFile back2 = ccd::truth_from_json(ccd::truth_to_json(t), "t.json");
  CHECK(back2.static_errors == t.static_errors);
  json j = ccd::truth_to_json(t);
  j["static_events"][0]["exit_error"] = -1.0;
  CHECK(error_of(j).find("static_events[0].exit_error: must be >= 0") != std::string::npos);
  j = ccd::truth_to_json(t);
  j["static_events"][1]["grazing"] = 1;
  CHECK(error_of(j).find("static_events[1].grazing") != std::string::npos);
}

TEST_CASE("truth files carry the undecided flag, and files without it read grazing events as undecided",
          "[truth][io][undecided]") {
  TruthFile t = sample();
  ccd::EventError undecided{0.5, 0.5, true};
  undecided.undecided = true;
  ccd::EventError static_undecided{0.25, 0.125, true};
  static_undecided.undecided = true;
  t.errors = {{0.0, 0.0, false}, undecided, {0.0, 0.5e-12, false}};
  t.has_scenery = true;
  t.static_events = {{2, 0, 0.5, 0.75}, {0, 1, 1.0, 1.0}};
  t.static_errors = {{1e-9, 1e-9, false}, static_undecided};
  const json j = json::parse(ccd::truth_to_text(t));
  CHECK(j["events"][1]["undecided"] == true);
  CHECK_FALSE(j["events"][0].contains("undecided"));
  CHECK_FALSE(j["events"][2].contains("undecided"));
  CHECK(j["static_events"][1]["undecided"] == true);
  CHECK_FALSE(j["static_events"][0].contains("undecided"));
  const TruthFile back = ccd::truth_from_json(j, "t.json");
  CHECK(back.errors == t.errors);
  CHECK(back.static_errors == t.static_errors);
  CHECK(back.errors[1].undecided);
  CHECK_FALSE(back.errors[0].undecided);

  SECTION("grazing but decided is written as such and reads back") {
    t.errors[1].undecided = false;
    const json k = json::parse(ccd::truth_to_text(t));
    CHECK(k["events"][1]["undecided"] == false);
    CHECK(ccd::truth_from_json(k, "t.json").errors == t.errors);
  }
  SECTION("a file written before the field: its grazing events are undecided, the others not") {
    json old = j;
    old["events"][1].erase("undecided");
    old["static_events"][1].erase("undecided");
    const TruthFile o = ccd::truth_from_json(old, "t.json");
    CHECK(o.errors[1].undecided);
    CHECK_FALSE(o.errors[0].undecided);
    CHECK(o.static_errors[1].undecided);
    CHECK_FALSE(o.static_errors[0].undecided);
  }
  SECTION("a non-boolean undecided names the file and the field") {
    json bad = j;
    bad["events"][1]["undecided"] = "yes";
    CHECK(error_of(bad) == "t.json: events[1].undecided: must be true or false");
    json bad_static = j;
    bad_static["static_events"][0]["undecided"] = 0;
    CHECK(error_of(bad_static) == "t.json: static_events[0].undecided: must be true or false");
  }
}

}  // namespace ccd_truth_truth_io_test
