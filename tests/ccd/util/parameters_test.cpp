#include <ccd/util/parameters.hpp>
#include <generators/generator_parameters.hpp>

#include <catch2/catch.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ccd_util_parameters_test {

using ccd::ParameterKind;
using ccd::ParameterSpec;
using ccd::ParameterValue;
using nlohmann::json;

namespace {

constexpr ParameterSpec kSpecs[] = {
    ccdlab::kSeedParameter,
    ccdlab::kBodiesParameter,
    ccdlab::kOffsetParameter,
    {"fraction", 0.02, "volume fraction", ParameterKind::Real, ccdlab::kVolumeFraction},
};

std::string error_of(const std::vector<ParameterValue>& given) {
  try {
    ccd::resolve_parameters(kSpecs, given);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string text_error_of(const std::string& argument) {
  try {
    ccd::parameter_value_from_text(argument);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string json_error_of(const json& j) {
  try {
    ccd::parameter_values_from_json(j);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("missing parameters take their defaults", "[generators]") {
  const ccd::ParameterSet p = ccd::resolve_parameters(kSpecs, {});
  CHECK(p.integer("seed") == 1);
  CHECK(p.integer("bodies") == 1000);
  CHECK(p.number("fraction") == 0.02);
  CHECK(p.vector("offset") == ccd::Vec3::Zero());
  CHECK(p.to_json() == json::parse(R"({"seed": 1, "bodies": 1000, "offset": [0, 0, 0], "fraction": 0.02})"));
  CHECK_THROWS_AS(p.number("undeclared"), std::logic_error);
}

TEST_CASE("command-line text and JSON give the same parameters", "[generators]") {
  const std::vector<ParameterValue> from_text = {ccd::parameter_value_from_text("bodies=2000"),
                                                 ccd::parameter_value_from_text("seed=7"),
                                                 ccd::parameter_value_from_text("offset=1e6,-2.5,1.25e-1"),
                                                 ccd::parameter_value_from_text("fraction=.125")};
  const std::vector<ParameterValue> from_json = ccd::parameter_values_from_json(
      json::parse(R"({"bodies": 2000, "seed": 7, "offset": [1e6, -2.5, 0.125], "fraction": 0.125})"));
  const json a = ccd::resolve_parameters(kSpecs, from_text).to_json();
  const json b = ccd::resolve_parameters(kSpecs, from_json).to_json();
  CHECK(a == b);
  CHECK(a["offset"] == json::array({1e6, -2.5, 0.125}));
  SECTION("a scalar offset applies to all axes") {
    const ccd::ParameterSet p =
        ccd::resolve_parameters(kSpecs, std::vector{ccd::parameter_value_from_text("offset=1e6")});
    CHECK(p.vector("offset") == ccd::Vec3(1e6, 1e6, 1e6));
  }
  SECTION("null JSON means no parameters") { CHECK(ccd::parameter_values_from_json(json()).empty()); }
}

TEST_CASE("bad parameters name the parameter and the rule", "[generators]") {
  auto one = [](const char* name, std::vector<double> v) { return std::vector{ParameterValue{name, std::move(v)}}; };
  SECTION("unknown names are all listed, with the valid ones") {
    CHECK(error_of({{"radius", {1}}, {"bodies", {2}}, {"colour", {3}}}) ==
          "unknown parameters 'radius', 'colour'; valid parameters: seed, bodies, offset, fraction");
    CHECK(error_of(one("radius", {1})) == "unknown parameter 'radius'; valid parameters: seed, bodies, offset, fraction");
  }
  SECTION("bodies must be an integer >= 0") {
    CHECK(error_of(one("bodies", {2.5})) == "parameter 'bodies': must be an integer in [0, 1e+08] (got 2.5)");
    CHECK(error_of(one("bodies", {-1})) == "parameter 'bodies': must be an integer in [0, 1e+08] (got -1)");
    CHECK(error_of(one("bodies", {0})).empty());
  }
  SECTION("fractions lie in the open interval (0, 0.5)") {
    CHECK(error_of(one("fraction", {0.5})) == "parameter 'fraction': must be a number in (0, 0.5) (got 0.5)");
    CHECK(error_of(one("fraction", {0.0})) == "parameter 'fraction': must be a number in (0, 0.5) (got 0)");
    CHECK(error_of(one("fraction", {0.49})).empty());
  }
  SECTION("NaN and infinity are out of every range") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(error_of(one("fraction", {nan})) == "parameter 'fraction': must be a number in (0, 0.5) (got nan)");
    CHECK(error_of(one("offset", {0, inf, 0})).rfind("parameter 'offset': must be one number or three", 0) == 0);
  }
  SECTION("count of numbers") {
    CHECK(error_of(one("offset", {1, 2})) == "parameter 'offset': expects one number or three (got 2)");
    CHECK(error_of(one("seed", {1, 2, 3})) == "parameter 'seed': expects one number (got 3)");
  }
  SECTION("given twice") {
    CHECK(error_of({{"seed", {1}}, {"seed", {2}}}) == "parameter 'seed': given more than once");
  }
  SECTION("seed limits: 2^53 is exact, beyond is refused") {
    CHECK(error_of(one("seed", {9007199254740992.0})).empty());
    CHECK(json_error_of(json::parse(R"({"seed": 9007199254740993})")) ==
          "parameter 'seed': integer 9007199254740993 is too large to be exact (|x| > 2^53)");
  }
}

TEST_CASE("command-line values must be numbers, read in full", "[generators]") {
  CHECK(text_error_of("bodies=abc") == "parameter 'bodies': 'abc' is not a number");
  CHECK(text_error_of("bodies=10x") == "parameter 'bodies': '10x' is not a number");
  CHECK(text_error_of("bodies=") == "parameter 'bodies': '' is not a number");
  CHECK(text_error_of("offset=1,,2") == "parameter 'offset': '' is not a number");
  CHECK(text_error_of("horizon=1e999") == "parameter 'horizon': '1e999' is not a number");
  CHECK(text_error_of("bodies") == "expected NAME=VALUE, got 'bodies'");
  CHECK(text_error_of("=3") == "expected NAME=VALUE, got '=3'");
  CHECK(ccd::parameter_value_from_text("offset=-1e6").values == std::vector<double>{-1e6});
}

TEST_CASE("JSON values must be numbers or arrays of numbers", "[generators]") {
  CHECK(json_error_of(json::parse(R"({"bodies": "10"})")) ==
        R"(parameter 'bodies': must be a number or an array of numbers (got "10"))");
  CHECK(json_error_of(json::parse(R"({"bodies": true})")) ==
        "parameter 'bodies': must be a number or an array of numbers (got true)");
  CHECK(json_error_of(json::parse(R"({"offset": []})")) ==
        "parameter 'offset': must be a number or an array of numbers (got [])");
  CHECK(json_error_of(json::parse("[1, 2]")) == "generator parameters must be a JSON object {\"name\": number, ...}");
}

TEST_CASE("range descriptions read as rules", "[generators]") {
  CHECK(ccd::describe_range(kSpecs[1]) == "an integer in [0, 1e+08]");
  CHECK(ccd::describe_range(kSpecs[3]) == "a number in (0, 0.5)");
  CHECK(ccd::describe_range({"x", 0.0, "", ParameterKind::Real, {0.0, std::numeric_limits<double>::max(), true, false}}) ==
        "a number > 0");
  CHECK(ccd::describe_range({"x", 0.0, "", ParameterKind::Real, {}}) == "a finite number");
  CHECK(ccd::format_number(0.1) == "0.1");
  CHECK(ccd::format_number(1e6) == "1e+06");
}

TEST_CASE("registry options are read from NAME:OPTIONS text", "[parameters]") {
  using ccd::option_values_from_text;
  SECTION("name=value pairs, in order") {
    const auto v = option_values_from_text("cell=2.5,threads=2", "");
    REQUIRE(v.size() == 2);
    CHECK(v[0].name == "cell");
    CHECK(v[0].values == std::vector<double>{2.5});
    CHECK(v[1].name == "threads");
    CHECK(v[1].values == std::vector<double>{2.0});
  }
  SECTION("a bare first value is the table's first parameter: horn:4 is horn:pieces=4") {
    const auto v = option_values_from_text("4", "pieces");
    REQUIRE(v.size() == 1);
    CHECK(v[0].name == "pieces");
    CHECK(v[0].values == std::vector<double>{4.0});
  }
  SECTION("errors name the bad part") {
    CHECK_THROWS_WITH(option_values_from_text("4", ""), Catch::Contains("expected NAME=VALUE, got '4'"));
    CHECK_THROWS_WITH(option_values_from_text("cell=1,2", ""), Catch::Contains("expected NAME=VALUE, got '2'"));
    CHECK_THROWS_WITH(option_values_from_text("cell=x", ""), Catch::Contains("parameter 'cell': 'x' is not a number"));
    CHECK_THROWS_WITH(option_values_from_text("cell=1,", ""), Catch::Contains("empty option"));
    CHECK_THROWS_WITH(option_values_from_text("=1", ""), Catch::Contains("expected NAME=VALUE"));
  }
}

TEST_CASE("a parameter is described with its default, unit, doc and range", "[parameters]") {
  constexpr ParameterSpec cell{"cell", 0.0, "smallest cell size", ParameterKind::Real, {0.0, 1e6}, "m"};
  CHECK(ccd::describe_parameter(cell) == "cell=0 m (smallest cell size; a number in [0, 1e+06])");
}

}  // namespace ccd_util_parameters_test
