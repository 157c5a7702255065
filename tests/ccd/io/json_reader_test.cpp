// The strict JSON reader: one meaning per file (no duplicate keys), bounded nesting and
// size, errors that name the file and the field path.
#include <ccd/io/json_reader.hpp>

#include <catch2/catch.hpp>
#include <string>

namespace ccd_io_json_reader_test {

using ccd::parse_json_text;

TEST_CASE("a key given twice in one object is an error naming its path", "[io][json]") {
  // nlohmann keeps the last of two equal keys: {"radius": -1, "radius": 0.5} read as 0.5.
  CHECK_THROWS_WITH(parse_json_text(R"({"a": 1, "a": 2})", "f.json"), "f.json: a: key given twice in one object");
  CHECK_THROWS_WITH(parse_json_text(R"({"bodies": [{"r": 1}, {"x": {"y": 1}, "r": -1, "r": 0.5}]})", "f.json"),
                    "f.json: bodies[1].r: key given twice in one object");
  CHECK_THROWS_WITH(parse_json_text(R"([[1, 2], [3, {"k": [], "k": {}}]])", "f.json"),
                    "f.json: [1][1].k: key given twice in one object");
  SECTION("equal keys in different objects are fine") {
    const auto j = parse_json_text(R"({"a": {"a": 1}, "b": [{"a": 1}, {"a": 2}]})", "f.json");
    CHECK(j["b"][1]["a"] == 2);
  }
}

TEST_CASE("nesting is bounded, numbers must fit a double", "[io][json]") {
  std::string deep(ccd::kMaxJsonDepth, '[');
  deep += std::string(ccd::kMaxJsonDepth, ']');
  CHECK_NOTHROW(parse_json_text(deep, "f.json"));
  const std::string deeper = "[" + deep + "]";
  CHECK_THROWS_WITH(parse_json_text(deeper, "f.json"), Catch::Matchers::EndsWith("nested deeper than 64 levels"));
  // A million open brackets: rejected at the 65th, not by a stack overflow.
  CHECK_THROWS_AS(parse_json_text(std::string(1000000, '['), "f.json"), ccd::InputError);
  CHECK_THROWS_WITH(parse_json_text(R"({"horizon": 1e999})", "f.json"),
                    Catch::Matchers::StartsWith("f.json: malformed JSON"));
}

TEST_CASE("read_json_file names the file for folders, devices and missing files", "[io][json]") {
  CHECK_THROWS_WITH(ccd::read_json_file("/"), "/: cannot open file: is a folder");
  CHECK_THROWS_WITH(ccd::read_json_file("/dev/zero"), Catch::Matchers::StartsWith("/dev/zero: malformed JSON"));
  CHECK_THROWS_WITH(ccd::read_json_file("/dev/null"), Catch::Matchers::StartsWith("/dev/null: malformed JSON"));
  CHECK_THROWS_WITH(ccd::read_json_file("/no/such/file.json"),
                    "/no/such/file.json: cannot open file: No such file or directory");
}

TEST_CASE("JsonReader::count and friends name the field", "[io][json]") {
  const std::string file = "f.json";
  const ccd::JsonReader r{file};
  const auto j = parse_json_text(R"({"n": 3, "neg": -1, "x": 2.5, "s": "t", "b": true})", file);
  CHECK(r.count(j["n"], "n", 10) == 3);
  CHECK_THROWS_WITH(r.count(j["n"], "n", 2), "f.json: n: must be an integer in [0, 2]");
  CHECK_THROWS_WITH(r.count(j["neg"], "neg", 10), "f.json: neg: must be an integer in [0, 10]");
  CHECK_THROWS_WITH(r.count(j["x"], "x", 10), "f.json: x: must be an integer in [0, 10]");
  CHECK_THROWS_WITH(r.string(j["x"], "x"), "f.json: x: must be a string");
  CHECK_THROWS_WITH(r.boolean(j["s"], "s"), "f.json: s: must be true or false");
  CHECK(r.boolean(j["b"], "b"));
}

TEST_CASE("only_fields: an unknown field is an error with the nearest known name", "[io][json]") {
  const std::string file = "scene.json";
  const ccd::JsonReader r{file};
  const auto body = parse_json_text(R"({"radius": 1, "position": [0, 0, 0], "velocty": [1, 0, 0]})", file);
  CHECK_THROWS_WITH(r.only_fields(body, "bodies[3]", {"radius", "position", "velocity", "acceleration"}),
                    R"(scene.json: bodies[3].velocty: unknown field (did you mean "velocity"?))");
  SECTION("a name far from every known one lists them") {
    const auto j = parse_json_text(R"({"radius": 1, "colour": "red"})", file);
    CHECK_THROWS_WITH(r.only_fields(j, "bodies[0]", {"radius", "position"}),
                      "scene.json: bodies[0].colour: unknown field (known: radius, position)");
  }
  SECTION("at the top level the field is named alone") {
    const auto j = parse_json_text(R"({"horizn": 1})", file);
    CHECK_THROWS_WITH(r.only_fields(j, "", {"format", "horizon"}),
                      R"(scene.json: horizn: unknown field (did you mean "horizon"?))");
  }
  SECTION("comment is allowed in every object, known fields pass") {
    const auto j = parse_json_text(R"({"comment": ["any", "note"], "radius": 1})", file);
    CHECK_NOTHROW(r.only_fields(j, "bodies[0]", {"radius"}));
  }
  SECTION("a key with control characters is shown escaped, on one line") {
    const auto j = parse_json_text("{\"a\\nb\": 1}", file);
    CHECK_THROWS_WITH(r.only_fields(j, "", {"ab"}), R"(scene.json: "a\nb": unknown field (did you mean "ab"?))");
  }
}

}  // namespace ccd_io_json_reader_test
