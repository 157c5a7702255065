// Every registered broad phase against `brute`, pair for pair, on generated box sets and
// frame sequences. A new registry entry is picked up by GENERATE with no edit here.
#include <ccd/broad_phase/grid.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace ccd_broad_phase_registry_test {

using ccd::Aabb;
using ccd::BodyPair;
using ccd::Vec3;

namespace {

std::vector<BodyPair> sorted_pairs(ccd::BroadPhase& bp, const std::vector<Aabb>& boxes) {
  std::vector<BodyPair> out{{7, 3}};  // stale content: find_pairs must clear it
  bp.find_pairs(boxes, out);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<BodyPair> reference_pairs(const std::vector<Aabb>& boxes) {
  auto brute = ccd::find_broad_phase("brute").make();
  return sorted_pairs(*brute, boxes);
}

// The method's pairs are brute force's: each once, with a < b.
void check_against_brute(ccd::BroadPhase& bp, const std::vector<Aabb>& boxes) {
  const std::vector<BodyPair> got = sorted_pairs(bp, boxes);
  for (const BodyPair& p : got) REQUIRE(p.a < p.b);
  REQUIRE(std::adjacent_find(got.begin(), got.end()) == got.end());
  const std::vector<BodyPair> want = reference_pairs(boxes);
  REQUIRE(got.size() == want.size());
  REQUIRE(got == want);
}

Aabb box(const Vec3& c, const Vec3& half) { return {c - half, c + half}; }

std::vector<Aabb> gas(std::size_t n, double side, double rmin, double rmax, std::uint64_t seed,
                      const Vec3& offset = Vec3::Zero()) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> pos(0, side), rad(rmin, rmax);
  std::vector<Aabb> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c(pos(gen), pos(gen), pos(gen));
    out.push_back(box(c + offset, Vec3(rad(gen), rad(gen), rad(gen))));
  }
  return out;
}

// Unit cubes [i, i+1] x [j, j+1] x [k, k+1]: faces, edges and corners touch exactly, and
// many coordinates are equal. Every second cube shrunk to [i, i+0.5] (still touching its
// lower neighbours, separated from its upper ones).
std::vector<Aabb> lattice(int m, double offset) {
  std::vector<Aabb> out;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        const Vec3 lo(offset + i, offset + j, offset + k);
        const double e = ((i + j + k) % 2 == 0) ? 1.0 : 0.5;
        out.push_back({lo, lo + Vec3::Constant(e)});
      }
  return out;
}

// Log-uniform extents from 0.01 to 10: three orders of magnitude.
std::vector<Aabb> mixed_sizes(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> pos(0, 40), lg(std::log(0.005), std::log(5.0));
  std::vector<Aabb> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c(pos(gen), pos(gen), pos(gen));
    const double h = std::exp(lg(gen));
    out.push_back(box(c, Vec3(h, h * (0.5 + 0.5 * (i % 3)), h)));
  }
  return out;
}

}  // namespace

TEST_CASE("the registry finds its entries by name", "[broad_phase]") {
  REQUIRE(ccd::broad_phase_registry().size() >= 5);
  for (const auto& info : ccd::broad_phase_registry()) CHECK(ccd::find_broad_phase(info.name).name == info.name);
  CHECK_THROWS_AS(ccd::find_broad_phase("no-such-method"), std::invalid_argument);
}

TEST_CASE("broad-phase options are a table with units and defaults, settable by spec", "[broad_phase]") {
  for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
    INFO(info.name);
    for (const ccd::ParameterSpec& p : info.parameters) {
      CHECK(!p.unit.empty());
      CHECK(p.range.contains(p.default_value));
    }
    const ccd::BroadPhaseSpec spec = ccd::parse_broad_phase(info.name);
    CHECK(spec.info == &info);
    CHECK(spec.options.to_json().size() == info.parameters.size());
  }
  SECTION("grid:cell=2.5,threads=2") {
    const ccd::BroadPhaseSpec spec = ccd::parse_broad_phase("grid:cell=2.5,threads=2");
    CHECK(spec.options.to_json() == nlohmann::json{{"cell", 2.5}, {"reuse", 32}, {"threads", 2}});
    // Unit boxes: the largest extent is 1, so the cell is the option's 2.5 (times 1 + 2^-20).
    auto grid = spec.make();
    std::vector<BodyPair> pairs;
    grid->find_pairs(std::vector<Aabb>{{Vec3::Zero(), Vec3::Ones()}, {Vec3::Constant(4), Vec3::Constant(5)}}, pairs);
    CHECK(dynamic_cast<const ccd::UniformGrid&>(*grid).cell_size() == Approx(2.5).epsilon(1e-5));
    CHECK(dynamic_cast<const ccd::UniformGrid&>(*grid).cell_size() >= 2.5);
  }
  SECTION("the defaults") {
    CHECK(ccd::parse_broad_phase("grid").options.to_json() ==
          nlohmann::json{{"cell", 0.0}, {"reuse", 32}, {"threads", 1}});
    CHECK(ccd::parse_broad_phase("hgrid").options.to_json() == nlohmann::json{{"reuse", 32}});
    CHECK(ccd::parse_broad_phase("sap").options.to_json() == nlohmann::json{{"swaps_per_endpoint", 2}});
    CHECK(ccd::parse_broad_phase("rtree").options.to_json() == nlohmann::json::object());
  }
  SECTION("bad specs name the bad part") {
    CHECK_THROWS_WITH(ccd::parse_broad_phase("grid:cel=2"), Catch::Contains("unknown parameter 'cel'"));
    CHECK_THROWS_WITH(ccd::parse_broad_phase("grid:threads=0"), Catch::Contains("parameter 'threads'"));
    CHECK_THROWS_WITH(ccd::parse_broad_phase("grid:2"), Catch::Contains("expected NAME=VALUE"));
    CHECK_THROWS_WITH(ccd::parse_broad_phase("brute:x=1"), Catch::Contains("it takes none"));
    CHECK_THROWS_WITH(ccd::parse_broad_phase("gird"), Catch::Contains("unknown broad phase 'gird'"));
  }
}

TEST_CASE("every broad phase equals brute force on static box sets", "[broad_phase]") {
  const auto& info = GENERATE(from_range(ccd::broad_phase_registry().begin(), ccd::broad_phase_registry().end()));
  CAPTURE(std::string(info.name));
  auto bp = info.make();

  SECTION("N = 0, 1, 2") {
    check_against_brute(*bp, {});                                                        // no pairs
    check_against_brute(*bp, {box(Vec3(1, 2, 3), Vec3(1, 1, 1))});                       // no pairs
    check_against_brute(*bp, {box(Vec3(0, 0, 0), Vec3(1, 1, 1)), box(Vec3(1.5, 0, 0), Vec3(1, 1, 1))});  // overlap
    check_against_brute(*bp, {box(Vec3(0, 0, 0), Vec3(1, 1, 1)), box(Vec3(2, 0, 0), Vec3(1, 1, 1))});    // touching
    check_against_brute(*bp, {box(Vec3(0, 0, 0), Vec3(1, 1, 1)), box(Vec3(2, 2.5, 0), Vec3(1, 1, 1))});  // apart
  }
  SECTION("random gas") {
    check_against_brute(*bp, gas(500, 30.0, 0.2, 1.5, 11));
    check_against_brute(*bp, gas(300, 5.0, 0.1, 0.6, 12));  // dense
  }
  SECTION("equal coordinates: lattice of exactly touching boxes") { check_against_brute(*bp, lattice(7, 0.0)); }
  SECTION("coincident boxes") {
    std::vector<Aabb> boxes(40, box(Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5)));
    auto more = gas(60, 4.0, 0.1, 0.5, 13);
    boxes.insert(boxes.end(), more.begin(), more.end());
    check_against_brute(*bp, boxes);
  }
  SECTION("degenerate point boxes at equal coordinates") {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 30; ++i) boxes.push_back({Vec3(i % 3, 0, 0), Vec3(i % 3, 0, 0)});
    check_against_brute(*bp, boxes);  // points at the same place overlap (closed boxes)
  }
  SECTION("mixed sizes over three orders of magnitude") { check_against_brute(*bp, mixed_sizes(600, 14)); }
  SECTION("far from the origin: coordinates offset by 1e6") {
    check_against_brute(*bp, gas(400, 30.0, 0.2, 1.5, 15, Vec3(1e6, -1e6, 1e6)));
    check_against_brute(*bp, lattice(6, 1e6));  // 1e6 + integers: exact, still touching
  }
  SECTION("one instance across changing body counts") {
    check_against_brute(*bp, gas(200, 10.0, 0.2, 1.0, 16));
    check_against_brute(*bp, gas(50, 10.0, 0.2, 1.0, 17));
    check_against_brute(*bp, {});
    check_against_brute(*bp, gas(120, 10.0, 0.2, 1.0, 18));
  }
}

TEST_CASE("every broad phase equals brute force over frame sequences", "[broad_phase]") {
  const auto& info = GENERATE(from_range(ccd::broad_phase_registry().begin(), ccd::broad_phase_registry().end()));
  CAPTURE(std::string(info.name));
  auto bp = info.make();

  SECTION("moving gas reflecting in a box, 40 frames") {
    std::mt19937_64 gen(21);
    std::uniform_real_distribution<double> vel(-0.4, 0.4);
    std::vector<Aabb> boxes = gas(300, 22.0, 0.2, 1.2, 22);
    std::vector<Vec3> v(boxes.size());
    for (Vec3& x : v) x = Vec3(vel(gen), vel(gen), vel(gen));
    for (int f = 0; f < 40; ++f) {
      CAPTURE(f);
      check_against_brute(*bp, boxes);
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (int a = 0; a < 3; ++a)
          if ((boxes[i].lo[a] < 0 && v[i][a] < 0) || (boxes[i].hi[a] > 22 && v[i][a] > 0)) v[i][a] = -v[i][a];
        boxes[i].lo += v[i];
        boxes[i].hi += v[i];
      }
    }
  }
  SECTION("complete order reversal between frames, touching boxes") {
    // Frame 0: unit boxes at x = i (each touches its neighbours); frame 1: body i at
    // x = n-1-i, so every sorted order reverses; frame 2 reverses back.
    const int n = 300;
    std::vector<Aabb> a, b;
    for (int i = 0; i < n; ++i) {
      a.push_back({Vec3(i, 0, 0), Vec3(i + 1, 1, 1)});
      b.push_back({Vec3(n - 1 - i, 0, 0), Vec3(n - i, 1, 1)});
    }
    check_against_brute(*bp, a);
    check_against_brute(*bp, b);
    check_against_brute(*bp, a);
  }
  SECTION("balls falling along the sweep axis onto a floor") {
    // Wide spread along x (the largest-variance axis, so sweep and prune sweeps x), then
    // every ball falls along -x onto the floor x = 0 and rests there: the end is every
    // box overlapping every other on x, with many equal coordinates.
    std::mt19937_64 gen(23);
    std::uniform_real_distribution<double> px(0, 200), pyz(0, 12), speed(1, 6);
    const std::size_t n = 200;
    std::vector<Vec3> c(n);
    std::vector<double> s(n);
    for (std::size_t i = 0; i < n; ++i) {
      c[i] = Vec3(px(gen), pyz(gen), pyz(gen));
      s[i] = speed(gen);
    }
    std::vector<Aabb> boxes(n);
    for (int f = 0; f < 40; ++f) {
      CAPTURE(f);
      for (std::size_t i = 0; i < n; ++i) boxes[i] = box(c[i], Vec3(0.5, 0.5, 0.5));
      check_against_brute(*bp, boxes);
      for (std::size_t i = 0; i < n; ++i) c[i].x() = std::max(0.5, c[i].x() - s[i]);
    }
  }
}

}  // namespace ccd_broad_phase_registry_test
