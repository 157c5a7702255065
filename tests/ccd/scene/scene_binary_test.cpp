// The binary scene format (ccd/scene/scene_binary.hpp, docs/formats.md): a scene written
// and read back is the same scene bit for bit, with the digest of its JSON file; a damaged
// file (truncated at any byte, a wrong magic, version, flag, count or value) is refused with
// InputError naming the file and the field, never read out of bounds.
#include "binary_scene_support.hpp"
#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

namespace ccd_scene_scene_binary_test {

using ccd::test::same_bits;
using nlohmann::json;

namespace {

// Every field the format carries, with the values that break careless code: dyadic
// numbers, a negative zero, a body at rest, a body exactly on the walls' planes (radius
// from them), far from the origin, wrap-around on one axis, gravity, acceleration and
// velocity changes (several on one body, none on the next), a change at the time of the
// other kind's change.
ccd::Scene every_field() {
  ccd::Scene s;
  s.horizon = 2.0;
  s.gravity = ccd::Vec3(0.0, -9.8125, -0.0);
  s.box = ccd::WallBox{};
  s.box->min = ccd::Vec3(-1048576.0, 0.0, 0.0);
  s.box->max = ccd::Vec3(1048576.0, 64.0, 64.0);
  s.box->boundary = {ccd::Boundary::Reflect, ccd::Boundary::Wrap, ccd::Boundary::Reflect};
  ccd::Body a;
  a.radius = 0.5;
  a.position = ccd::Vec3(-1048575.5, 32.0, 0.5);  // on the x and z wall planes
  a.velocity = ccd::Vec3(0.125, -0.0, 3.0);
  a.acceleration = ccd::Vec3(0.0, 9.8125, 0.0);
  a.acceleration_changes = {{0.5, ccd::Vec3(1.0, 2.0, 3.0)}, {1.25, ccd::Vec3(-0.25, 0.0, 0.0)}};
  a.velocity_changes = {{0.5, ccd::Vec3(0.0, 0.0, -1.0)}};
  ccd::Body rest;  // zero velocity, no changes
  rest.radius = 0.25;
  rest.position = ccd::Vec3(1048575.75, 63.75, 63.75);  // against the far walls (y wraps: inside)
  ccd::Body jumps;
  jumps.radius = std::ldexp(1.0, -20);
  jumps.position = ccd::Vec3(0.1, 0.2, 0.3);  // not dyadic: every bit of the double kept
  jumps.velocity = ccd::Vec3(1.0 / 3.0, 0.0, 0.0);
  jumps.velocity_changes = {{0.25, ccd::Vec3(2.0, 0.0, 0.0)}, {0.75, ccd::Vec3(0.0, 0.0, 0.0)},
                            {1.999, ccd::Vec3(-1.0, 1.0, -1.0)}};
  s.bodies = {a, rest, jumps};
  return s;
}

// The bytes of `scene`'s binary file, read back as its JSON file would be.
ccd::Scene round_trip(const ccd::Scene& scene, std::string* digest = nullptr) {
  return ccd::scene_from_binary(ccd::scene_to_binary(scene, "s.json"), "s.ccds", digest);
}

std::string error_of_binary(const std::string& bytes) {
  try {
    ccd::scene_from_binary(bytes, "s.ccds");
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "";
}

template <class U>
void poke(std::string& bytes, std::size_t at, U value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);  // the tests run on little-endian machines
}

// Section offsets of a file with n bodies and ma, mv changes (docs/formats.md).
struct Layout {
  std::size_t radius, position, velocity, acceleration, acceleration_counts, velocity_counts, acceleration_changes,
      velocity_changes, end;
  Layout(std::size_t n, std::size_t ma, std::size_t mv) {
    radius = 192;
    position = radius + 8 * n;
    velocity = position + 24 * n;
    acceleration = velocity + 24 * n;
    acceleration_counts = acceleration + 24 * n;
    velocity_counts = acceleration_counts + 4 * n;
    acceleration_changes = velocity_counts + 4 * n;
    velocity_changes = acceleration_changes + 32 * ma;
    end = velocity_changes + 32 * mv;
  }
};

}  // namespace

TEST_CASE("a scene written in binary reads back bit for bit, with its JSON file's digest", "[scene][binary]") {
  const ccd::Scene original = every_field();
  REQUIRE_NOTHROW(ccd::validate_scene(original, "every_field"));
  // The scene as its JSON file gives it: the reference of the digest.
  const ccd::Scene from_json = ccd::scene_from_json(json::parse(ccd::scene_to_json(original).dump(1)), "s.json");
  REQUIRE(same_bits(from_json, original));
  std::string stored;
  const ccd::Scene back = round_trip(from_json, &stored);
  CHECK(same_bits(back, original));
  CHECK(std::signbit(back.bodies[0].velocity.y()));  // -0.0 stays -0.0
  CHECK(std::signbit(back.gravity.z()));
  CHECK(stored == ccd::scene_digest(from_json));
  CHECK(ccd::scene_digest(back) == stored);
  CHECK_NOTHROW(ccd::verify_binary_scene_digest(back, stored, "s.ccds"));
  // The layout: 192 bytes of header, 88 per body, 32 per change.
  CHECK(ccd::scene_to_binary(original, "s").size() == 192 + 88 * 3 + 32 * (2 + 1 + 3));

  SECTION("no box, no changes, no bodies") {
    ccd::Scene s;
    s.horizon = 1.0;
    CHECK(same_bits(round_trip(s), s));
    CHECK(ccd::scene_to_binary(s, "s").size() == 192);
    s.bodies.push_back(original.bodies[1]);
    CHECK(same_bits(round_trip(s), s));
    CHECK(ccd::scene_digest(round_trip(s)) == ccd::scene_digest(s));
  }
  SECTION("every boundary combination") {
    ccd::Scene s = original;
    for (int mask = 0; mask < 8; ++mask) {
      for (int k = 0; k < 3; ++k)
        s.box->boundary[static_cast<std::size_t>(k)] = (mask >> k) & 1 ? ccd::Boundary::Wrap : ccd::Boundary::Reflect;
      if (ccd::test::error_of(ccd::scene_to_json(s)).empty()) CHECK(same_bits(round_trip(s), s));
    }
  }
}

TEST_CASE("load_scene tells binary from JSON by the magic, not by the name", "[scene][binary]") {
  const ccd::Scene s = every_field();
  const auto dir = std::filesystem::temp_directory_path() / ("ccdlab-binary-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string binary_named_json = (dir / "scene.json").string(), json_named_ccds = (dir / "scene.ccds").string();
  ccd::save_binary_scene(s, binary_named_json);
  ccd::save_scene(s, json_named_ccds);
  CHECK(ccd::is_binary_scene_file(binary_named_json));
  CHECK_FALSE(ccd::is_binary_scene_file(json_named_ccds));
  CHECK_FALSE(ccd::is_binary_scene_file((dir / "missing").string()));
  CHECK_FALSE(ccd::is_binary_scene_file(dir.string()));  // a folder
  CHECK(same_bits(ccd::load_scene(binary_named_json), s));
  CHECK(same_bits(ccd::load_scene(json_named_ccds), s));
  // A file shorter than the magic is JSON to the sniffer, and bad JSON to the reader.
  { std::ofstream(dir / "short") << "\x89" "CC"; }
  CHECK_THROWS_AS(ccd::load_scene((dir / "short").string()), ccd::InputError);
  std::filesystem::remove_all(dir);
}

TEST_CASE("scenes with shapes, spin or scenery have no binary form", "[scene][binary]") {
  const json rigid = json::parse(R"({"format": "ccdlab-scene/2", "horizon": 1,
    "shapes": [{"name": "stick", "kind": "capsule", "half_length": 1, "radius": 0.1}],
    "bodies": [{"radius": 0.5, "position": [0, 0, 0]}, {"shape": "stick", "position": [5, 0, 0]}]})");
  const ccd::Scene s = ccd::scene_from_json(rigid, "r.json");
  REQUIRE(ccd::binary_scene_unsupported(s));
  CHECK(ccd::binary_scene_unsupported(s)->field == "shapes");
  CHECK_THROWS_WITH(ccd::scene_to_binary(s, "r.json"),
                    "r.json: shapes: the binary scene format carries sphere scenes only (no shapes, spin or scenery): "
                    "keep this scene as JSON");
  SECTION("a spinning sphere names its body") {
    json j = json::parse(R"({"format": "ccdlab-scene/2", "horizon": 1,
      "bodies": [{"radius": 0.5, "position": [0, 0, 0]}, {"radius": 0.5, "position": [5, 0, 0], "angular_velocity": [0, 0, 1]}]})");
    const ccd::Scene spin = ccd::scene_from_json(j, "r.json");
    REQUIRE(ccd::binary_scene_unsupported(spin));
    CHECK(ccd::binary_scene_unsupported(spin)->field == "bodies[1]");
  }
  SECTION("a version-2 file of plain spheres is a sphere scene and packs") {
    json j = json::parse(R"({"format": "ccdlab-scene/2", "horizon": 1, "bodies": [{"radius": 0.5, "position": [0, 0, 0]}]})");
    const ccd::Scene plain = ccd::scene_from_json(j, "r.json");
    CHECK_FALSE(ccd::binary_scene_unsupported(plain));
    CHECK(ccd::scene_digest(round_trip(plain)) == ccd::scene_digest(plain));
  }
}

TEST_CASE("a truncated binary scene is refused at every length, naming the section cut", "[scene][binary]") {
  const ccd::Scene s = every_field();
  const std::string bytes = ccd::scene_to_binary(s, "s");
  const Layout at(3, 2, 4);
  REQUIRE(bytes.size() == at.end);
  // Every proper prefix: an InputError (never a crash or a read past the end: the ASan
  // build checks the latter), naming the file.
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string e = error_of_binary(bytes.substr(0, n));
    CAPTURE(n, e);
    REQUIRE(e.rfind("s.ccds: ", 0) == 0);
  }
  // Cut at a section's first byte, or inside it: that section is named.
  auto cut = [&](std::size_t n) { return error_of_binary(bytes.substr(0, n)); };
  CHECK(cut(0) == "s.ccds: magic: not a binary scene (it does not start with the 8 bytes 89 43 43 44 53 0d 0a 1a)");
  CHECK(cut(100) == "s.ccds: header: truncated: the header has 192 bytes, the file 100");
  CHECK(cut(at.radius) == "s.ccds: radius: truncated: 3 bodies need 8 bytes each from byte 192, the file ends at byte 192");
  CHECK(cut(at.position + 5).rfind("s.ccds: position: truncated", 0) == 0);
  CHECK(cut(at.velocity).rfind("s.ccds: velocity: truncated", 0) == 0);
  CHECK(cut(at.acceleration).rfind("s.ccds: acceleration: truncated", 0) == 0);
  CHECK(cut(at.acceleration_counts).rfind("s.ccds: acceleration_change_counts: truncated", 0) == 0);
  CHECK(cut(at.velocity_counts).rfind("s.ccds: velocity_change_counts: truncated", 0) == 0);
  CHECK(cut(at.acceleration_changes).rfind("s.ccds: acceleration_changes: truncated", 0) == 0);
  CHECK(cut(at.velocity_changes).rfind("s.ccds: velocity_changes: truncated", 0) == 0);
  CHECK(cut(at.end - 1).rfind("s.ccds: velocity_changes: truncated", 0) == 0);
  // One byte too many.
  CHECK(error_of_binary(bytes + '\0') ==
        "s.ccds: length: 1 bytes after the last section (the file should end at byte " + std::to_string(at.end) + ")");
}

TEST_CASE("a damaged binary header or count is refused by name", "[scene][binary]") {
  const std::string good = ccd::scene_to_binary(every_field(), "s");
  std::string bytes = good;
  SECTION("magic") {
    bytes[0] = '{';
    CHECK(error_of_binary(bytes).rfind("s.ccds: magic: not a binary scene", 0) == 0);
  }
  SECTION("version") {
    poke<std::uint32_t>(bytes, 8, 2);
    CHECK(error_of_binary(bytes) == "s.ccds: version: 2 is not supported (this ccdlab reads version 1)");
  }
  SECTION("flags") {
    poke<std::uint32_t>(bytes, 12, 3);
    CHECK(error_of_binary(bytes) == "s.ccds: flags: unknown flags 2 (only bit 0, the box, is defined)");
  }
  SECTION("no box flag, but box bytes") {
    poke<std::uint32_t>(bytes, 12, 0);
    CHECK(error_of_binary(bytes) == "s.ccds: box: given while the flags say there is no box (its bytes must be 0)");
  }
  SECTION("a boundary byte") {
    bytes[185] = 2;
    CHECK(error_of_binary(bytes) == "s.ccds: box.boundary[1]: must be 0 (reflect) or 1 (wrap), not 2");
  }
  SECTION("reserved bytes") {
    bytes[191] = 1;
    CHECK(error_of_binary(bytes) == "s.ccds: reserved: header bytes 187 to 191 must be 0");
  }
  SECTION("the digest's text") {
    bytes[40] = 'G';
    CHECK(error_of_binary(bytes) == "s.ccds: digest: must be 64 lowercase hexadecimal digits");
  }
  SECTION("a digest of another scene: read, and caught by the check") {
    bytes[40] = bytes[40] == '0' ? '1' : '0';
    std::string stored;
    const ccd::Scene s = ccd::scene_from_binary(bytes, "s.ccds", &stored);
    CHECK_THROWS_WITH(ccd::verify_binary_scene_digest(s, stored, "s.ccds"),
                      Catch::Matchers::StartsWith("s.ccds: digest: the stored digest ") &&
                          Catch::Matchers::EndsWith("is not the scene's (" + ccd::scene_digest(s).substr(0, 12) +
                                                    "...): the file is corrupt"));
  }
  SECTION("a body count larger than the file") {
    poke<std::uint64_t>(bytes, 16, 4);
    CHECK(error_of_binary(bytes).rfind("s.ccds: ", 0) == 0);
    poke<std::uint64_t>(bytes, 16, std::numeric_limits<std::uint64_t>::max());
    CHECK(error_of_binary(bytes).rfind("s.ccds: radius: truncated: 18446744073709551615 bodies", 0) == 0);
  }
  SECTION("a body count smaller than the file") {
    poke<std::uint64_t>(bytes, 16, 2);
    CHECK(error_of_binary(bytes).rfind("s.ccds: ", 0) == 0);
  }
  SECTION("change totals against the per-body counts") {
    const Layout at(3, 2, 4);
    poke<std::uint32_t>(bytes, at.acceleration_counts, 1);  // body 0: 1 of its 2, the total still 2
    CHECK(error_of_binary(bytes) == "s.ccds: acceleration_change_counts: add up to 1, the header says 2");
    bytes = good;
    poke<std::uint32_t>(bytes, at.velocity_counts + 8, 0xffffffffu);  // body 2: 2^32 - 1 changes
    CHECK(error_of_binary(bytes) == "s.ccds: velocity_change_counts: add up to 4294967296, the header says 4");
    bytes = good;
    poke<std::uint64_t>(bytes, 24, 1u << 30);  // a header total larger than the file
    CHECK(error_of_binary(bytes).rfind("s.ccds: acceleration_changes: truncated: 1073741824 changes", 0) == 0);
  }
}

TEST_CASE("a binary scene's values are validated like the JSON file's, with the same messages", "[scene][binary]") {
  // Each damage is applied to the scene in memory, written both ways (the writers do not
  // validate), and read back: the JSON and binary readers give the same message.
  using Damage = void (*)(ccd::Scene&);
  const std::pair<const char*, Damage> cases[] = {
      {"radius <= 0", [](ccd::Scene& s) { s.bodies[1].radius = -0.25; }},
      {"radius 0", [](ccd::Scene& s) { s.bodies[1].radius = 0.0; }},
      {"a body outside the box", [](ccd::Scene& s) { s.bodies[0].position.x() = -1048576.0; }},
      {"a huge velocity", [](ccd::Scene& s) { s.bodies[2].velocity.y() = 1e30; }},
      {"horizon <= 0", [](ccd::Scene& s) { s.horizon = 0.0; }},
      {"box min >= max", [](ccd::Scene& s) { s.box->max.z() = 0.0; }},
      {"changes out of order", [](ccd::Scene& s) { s.bodies[2].velocity_changes[1].t = 0.25; }},
      {"a change at the horizon", [](ccd::Scene& s) { s.bodies[0].acceleration_changes[1].t = 2.0; }},
      {"a wrapped centre outside", [](ccd::Scene& s) { s.bodies[1].position.y() = 64.5; }},
  };
  for (const auto& [name, damage] : cases) {
    ccd::Scene s = every_field();
    damage(s);
    CAPTURE(name);
    std::string json_error = ccd::test::error_of(ccd::scene_to_json(s));
    REQUIRE(json_error.rfind("s.json: ", 0) == 0);
    CHECK("s.ccds: " + json_error.substr(8) == error_of_binary(ccd::scene_to_binary(s, "s")));
  }
  // What JSON cannot spell: NaN and infinity are refused by name too.
  ccd::Scene s = every_field();
  s.bodies[1].radius = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_of_binary(ccd::scene_to_binary(s, "s")) == "s.ccds: bodies[1].radius: must be finite");
  s = every_field();
  s.bodies[2].velocity_changes[0].velocity.z() = -std::numeric_limits<double>::infinity();
  CHECK(error_of_binary(ccd::scene_to_binary(s, "s")) == "s.ccds: bodies[2].velocity_changes[0].velocity[2]: must be finite");
  s = every_field();
  s.gravity.x() = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_of_binary(ccd::scene_to_binary(s, "s")) == "s.ccds: gravity[0]: must be finite");
}

}  // namespace ccd_scene_scene_binary_test
