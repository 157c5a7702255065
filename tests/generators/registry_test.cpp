// Properties every generator of the registry must have.
#include "generator_test_support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace generators_registry_test {

using ccdlab::testing::make;
using ccdlab::testing::same_scene;
using nlohmann::json;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// Parameters under which every generator draws something random (a lattice at rest is
// the same for every seed).
json random_params(std::string_view generator, int bodies, int seed) {
  json p = {{"bodies", bodies}, {"seed", seed}};
  if (generator == "lattice") p["speed"] = 1.0;
  return p;
}

std::string generator_name() {
  const auto names = [] {
    std::vector<std::string> out;
    for (const ccdlab::Generator& g : ccdlab::generators()) out.emplace_back(g.name);
    return out;
  }();
  return GENERATE_COPY(from_range(names));
}

}  // namespace

TEST_CASE("the registry holds the fifteen generators, each with the common parameters first", "[generators]") {
  std::set<std::string> names;
  for (const ccdlab::Generator& g : ccdlab::generators()) {
    names.insert(std::string(g.name));
    REQUIRE(g.parameters.size() >= 4);
    CHECK(g.parameters[0].name == "seed");
    CHECK(g.parameters[1].name == "bodies");
    CHECK(g.parameters[2].name == "horizon");
    CHECK(g.parameters[3].name == "offset");
    std::set<std::string_view> params;
    for (const ccdlab::ParameterSpec& s : g.parameters) {
      CHECK(params.insert(s.name).second);  // no name twice
      CHECK(!s.doc.empty());
      CHECK(s.range.contains(s.default_value));
    }
  }
  CHECK(names == std::set<std::string>{"gas", "rain", "bullets", "swarm", "lattice", "mixed", "grazing", "sticks",
                                       "plates", "crates", "rocks", "floor_ramp", "bowl", "pinball", "tumble"});
}

TEST_CASE("every generator is deterministic in its seed", "[generators]") {
  const std::string g = generator_name();
  CAPTURE(g);
  const ccd::Scene a = make(g, random_params(g, 60, 11));
  const ccd::Scene b = make(g, random_params(g, 60, 11));
  const ccd::Scene c = make(g, random_params(g, 60, 12));
  CHECK(same_scene(a, b));
  CHECK(!same_scene(a, c));
}

TEST_CASE("every generator makes the requested count of valid bodies", "[generators]") {
  const std::string g = generator_name();
  const int n = GENERATE(0, 1, 2, 3, 27, 100);
  CAPTURE(g, n);
  const ccd::Scene s = make(g, random_params(g, n, 3));
  CHECK(s.bodies.size() == static_cast<std::size_t>(n));
  REQUIRE(s.box);
  CHECK_NOTHROW(ccd::validate_scene(s, g));
  CHECK(s.horizon == 1.0);
  SECTION("with the defaults too") {
    const ccd::Scene d = make(g, json::object());
    CHECK(d.bodies.size() == 1000);
    CHECK_NOTHROW(ccd::validate_scene(d, g));
  }
  SECTION("horizon is passed through") { CHECK(make(g, {{"bodies", n}, {"horizon", 2.5}}).horizon == 2.5); }
}

TEST_CASE("offset moves every body by exactly the offset", "[generators]") {
  const std::string g = generator_name();
  const json offset = GENERATE(json(1e6), json::array({1e6, -2e6, 3.25e6}), json(-1e12), json(0.1));
  CAPTURE(g, offset.dump());
  json p = random_params(g, 200, 5);
  const ccd::Scene base = make(g, p);
  p["offset"] = offset;
  const ccd::Scene moved = make(g, p);
  const ccd::Vec3 o = offset.is_array() ? ccd::Vec3(offset[0].get<double>(), offset[1].get<double>(), offset[2].get<double>())
                                        : ccd::Vec3::Constant(offset.get<double>());
  REQUIRE(moved.bodies.size() == base.bodies.size());
  CHECK_NOTHROW(ccd::validate_scene(moved, g));
  for (std::size_t i = 0; i < base.bodies.size(); ++i) {
    const ccd::Body& a = base.bodies[i];
    const ccd::Body& b = moved.bodies[i];
    CHECK(b.position == ccd::Vec3(a.position + o));  // the same floating-point additions
    CHECK(b.radius == a.radius);
    CHECK(b.velocity == a.velocity);
    CHECK(b.acceleration == a.acceleration);
    REQUIRE(b.acceleration_changes.size() == a.acceleration_changes.size());
    for (std::size_t k = 0; k < a.acceleration_changes.size(); ++k) {
      CHECK(b.acceleration_changes[k].t == a.acceleration_changes[k].t);
      CHECK(b.acceleration_changes[k].acceleration == a.acceleration_changes[k].acceleration);
    }
  }
  CHECK(moved.gravity == base.gravity);
  // The box moves by the offset, widened only where rounding at |offset| put a body a few
  // ulps outside: fl(p + o) and fl(min + o) each round by at most ulp(|o| + side) / 2,
  // and fl(p - r) once more, so the widening is below 4 eps (|o| + side) per wall.
  for (int a = 0; a < 3; ++a) {
    const double slack = 4 * eps * (std::abs(o[a]) + base.box->max[a]);
    const double lo = base.box->min[a] + o[a];
    const double hi = base.box->max[a] + o[a];
    CHECK(moved.box->min[a] <= lo);
    CHECK(moved.box->min[a] >= lo - slack);
    CHECK(moved.box->max[a] >= hi);
    CHECK(moved.box->max[a] <= hi + slack);
  }
  SECTION("a scalar offset equals the same number on every axis") {
    json q = random_params(g, 20, 5);
    q["offset"] = 1e6;
    json r = q;
    r["offset"] = {1e6, 1e6, 1e6};
    CHECK(same_scene(make(g, q), make(g, r)));
  }
}

TEST_CASE("bad generator names and parameters are refused by name", "[generators]") {
  CHECK_THROWS_WITH(make("plasma", json::object()),
                    "unknown generator 'plasma'; valid generators: gas, rain, bullets, swarm, lattice, mixed, grazing, "
                    "sticks, plates, crates, rocks, floor_ramp, bowl, pinball, tumble");
  CHECK_THROWS_WITH(make("gas", {{"bodies", 10}, {"radius", 1}}),
                    Catch::Matchers::StartsWith("unknown parameter 'radius'; valid parameters: seed, bodies"));
  CHECK_THROWS_WITH(make("gas", {{"bodies", -3}}), Catch::Matchers::StartsWith("parameter 'bodies': must be"));
  CHECK_THROWS_WITH(make("gas", {{"r_min", 2.0}}), "r_min (2) must be <= r_max (1.5)");
  CHECK_THROWS_AS(make("swarm", {{"regular", 2}}), std::invalid_argument);
}

TEST_CASE("docs/generators.md documents every generator's parameters and defaults", "[generators]") {
  std::ifstream in(std::string(CCDLAB_SOURCE_DIR) + "/docs/generators.md");
  REQUIRE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  for (const ccdlab::Generator& g : ccdlab::generators()) {
    CAPTURE(g.name);
    const std::size_t begin = doc.find("## `" + std::string(g.name) + "`");
    REQUIRE(begin != std::string::npos);
    const std::size_t end = doc.find("\n## ", begin + 1);
    const std::string section = doc.substr(begin, end - begin);
    for (const ccdlab::ParameterSpec& s : g.parameters) {
      CAPTURE(s.name);
      CHECK(section.find("| `" + std::string(s.name) + "` | " + ccdlab::format_number(s.default_value) + " |") !=
            std::string::npos);
    }
  }
}

}  // namespace generators_registry_test
