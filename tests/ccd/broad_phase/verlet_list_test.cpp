// The Verlet list of `grid` and `hgrid` (ccd/broad_phase/verlet_list.hpp) against brute
// force over long runs of frames: bodies drifting, bouncing, jumping, resting and
// touching exactly, body counts changing, motions too fast for a list (the back-off). The
// claim: every frame reports brute force's set of pairs, whatever the frames the list
// served; `rebuilt` tells the served frames, and a served frame lists the same pairs as the
// rebuild before it, in its order.
#include <ccd/broad_phase/brute_force.hpp>
#include <ccd/broad_phase/grid.hpp>
#include <ccd/broad_phase/hgrid.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>

namespace ccd_broad_phase_verlet_list_test {

using ccd::Aabb;
using ccd::BodyPair;
using ccd::Vec3;

namespace {

std::vector<BodyPair> sorted(std::vector<BodyPair> p) {
  std::sort(p.begin(), p.end());
  return p;
}

// A gas of dyadic cubes in [0, 16]^3 moving with dyadic velocities, reflecting at the walls.
struct Gas {
  std::vector<Vec3> centre, velocity;
  std::vector<double> half;
  Gas(std::size_t n, double speed, std::uint64_t seed) {
    std::mt19937_64 gen(seed);
    std::uniform_int_distribution<int> cell(0, 255), size(2, 8), dir(-8, 8);
    for (std::size_t i = 0; i < n; ++i) {
      centre.emplace_back(cell(gen) / 16.0, cell(gen) / 16.0, cell(gen) / 16.0);
      velocity.emplace_back(Vec3(dir(gen), dir(gen), dir(gen)) * (speed / 8.0));
      half.push_back(size(gen) / 16.0);
    }
  }
  void step() {
    for (std::size_t i = 0; i < centre.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        centre[i][k] += velocity[i][k];
        if (centre[i][k] < 0.0 || centre[i][k] > 16.0) velocity[i][k] = -velocity[i][k];
      }
  }
  std::vector<Aabb> boxes() const {
    std::vector<Aabb> out;
    for (std::size_t i = 0; i < centre.size(); ++i)
      out.push_back({centre[i].array() - half[i], centre[i].array() + half[i]});
    return out;
  }
};

struct RunCount {
  int frames = 0, rebuilds = 0;
};

// Every frame of `frames` against brute force; served frames (not rebuilt) must list the
// pairs of the frame's boxes among the last rebuild's order.
RunCount run(ccd::BroadPhase& bp, Gas& gas, int frames) {
  ccd::BruteForce brute;
  RunCount count;
  std::vector<BodyPair> got, want;
  for (int f = 0; f < frames; ++f) {
    const std::vector<Aabb> boxes = gas.boxes();
    got.assign(3, BodyPair{0, 1});  // stale content: find_pairs clears it
    bp.find_pairs(boxes, got);
    brute.find_pairs(boxes, want);
    INFO("frame " << f);
    REQUIRE(got.size() == want.size());
    REQUIRE(sorted(got) == sorted(want));
    ++count.frames;
    count.rebuilds += bp.stats().rebuilt;
    gas.step();
  }
  return count;
}

}  // namespace

TEST_CASE("grid and hgrid with a Verlet list report brute force's pairs on every frame", "[broad_phase][verlet]") {
  for (const char* spec : {"grid", "hgrid", "grid:reuse=1", "grid:reuse=64", "hgrid:reuse=3"}) {
    for (const double speed : {0.0, 1.0 / 256.0, 1.0 / 32.0}) {
      INFO(spec << " speed " << speed);
      Gas gas(300, speed, 7);
      const auto bp = ccd::parse_broad_phase(spec).make();
      const RunCount c = run(*bp, gas, 120);
      if (speed == 0.0) REQUIRE(c.rebuilds == 1);  // at rest: one list serves every frame
      if (speed == 1.0 / 256.0 && std::string(spec) != "grid:reuse=1") {  // a list for one frame's motion: no gain
        REQUIRE(c.rebuilds > 1);
        REQUIRE(c.rebuilds < c.frames / 2);  // slow drift: lists serve most frames
      }
    }
  }
}

TEST_CASE("reuse=0 rebuilds every frame and fast motion backs off to plain rebuilds", "[broad_phase][verlet]") {
  Gas slow(200, 1.0 / 256.0, 3);
  ccd::UniformGrid plain(ccd::GridOptions{.reuse = 0});
  REQUIRE(run(plain, slow, 40).rebuilds == 40);
  // Every body jumps by more than its box each frame: no list survives a frame.
  Gas fast(200, 2.0, 5);
  ccd::UniformGrid grid;
  REQUIRE(run(grid, fast, 200).rebuilds == 200);
  ccd::HierarchicalGrid hgrid;
  Gas fast2(200, 2.0, 5);
  REQUIRE(run(hgrid, fast2, 200).rebuilds == 200);
}

TEST_CASE("a Verlet list survives body count changes, touching boxes and a body leaving its grown box",
          "[broad_phase][verlet]") {
  ccd::UniformGrid grid;
  ccd::BruteForce brute;
  std::vector<BodyPair> got, want;
  // Three unit boxes in a row, touching at x = 1 and x = 2 (closed intervals).
  std::vector<Aabb> boxes = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(1, 0, 0), Vec3(2, 1, 1)},
                             {Vec3(2, 0, 0), Vec3(3, 1, 1)}};
  grid.find_pairs(boxes, got);
  REQUIRE(sorted(got) == std::vector<BodyPair>{{0, 1}, {1, 2}});
  REQUIRE(grid.stats().rebuilt);
  grid.find_pairs(boxes, got);  // unchanged: served
  REQUIRE_FALSE(grid.stats().rebuilt);
  REQUIRE(sorted(got) == std::vector<BodyPair>{{0, 1}, {1, 2}});
  // Box 2 moves off by 2^-40 inside its grown box (margin 3/64 on the first build): the
  // listed pair {1, 2} is tested and drops out without a rebuild.
  boxes[2] = {Vec3(2 + 0x1p-40, 0, 0), Vec3(3 + 0x1p-40, 1, 1)};
  grid.find_pairs(boxes, got);
  REQUIRE_FALSE(grid.stats().rebuilt);
  REQUIRE(sorted(got) == std::vector<BodyPair>{{0, 1}});
  // Box 0 jumps onto box 2: outside its grown box, so the frame rebuilds.
  boxes[0] = {Vec3(2.5, 0.5, 0.5), Vec3(3.5, 1.5, 1.5)};
  grid.find_pairs(boxes, got);
  REQUIRE(grid.stats().rebuilt);
  brute.find_pairs(boxes, want);
  REQUIRE(sorted(got) == sorted(want));
  // A fourth body: the count changed, so the list cannot serve.
  boxes.push_back({Vec3(0.5, 0.5, 0.5), Vec3(0.75, 0.75, 0.75)});
  grid.find_pairs(boxes, got);
  REQUIRE(grid.stats().rebuilt);
  brute.find_pairs(boxes, want);
  REQUIRE(sorted(got) == sorted(want));
  // Far from the origin: boxes at 2^40 with dyadic sizes, one touching.
  std::vector<Aabb> far = {{Vec3::Constant(0x1p40), Vec3::Constant(0x1p40 + 1)},
                           {Vec3::Constant(0x1p40 + 1), Vec3::Constant(0x1p40 + 2)},
                           {Vec3::Constant(0x1p40 + 2.5), Vec3::Constant(0x1p40 + 3)}};
  for (int f = 0; f < 4; ++f) {
    grid.find_pairs(far, got);
    brute.find_pairs(far, want);
    REQUIRE(sorted(got) == sorted(want));
    REQUIRE(sorted(got) == std::vector<BodyPair>{{0, 1}});
  }
}

}  // namespace ccd_broad_phase_verlet_list_test
