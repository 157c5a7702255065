// The ground truth's candidate finder against brute force: every (pair, window) and
// (body, polygon, window) whose closed boxes overlap, and nothing else, merged into runs of
// consecutive windows; on random scenes, scenes that wrap around, with scenery (a floor
// that covers every grid column), exactly touching boxes, far from the origin.
#include "../scene/periodic_scenes.hpp"

#include <ccd/broad_phase/static_index.hpp>
#include <ccd/truth/truth_candidates.hpp>
#include <tests/ccd/scene/body_builder.hpp>

#include <catch2/catch.hpp>
#include <random>
#include <set>
#include <tuple>

namespace ccd_truth_truth_candidates_test {

using ccd::Aabb;
using ccd::Scene;
using ccd::Trajectories;
using ccd::Vec3;
using ccd::test::body;

namespace {

using Entry = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;  // (a, b, window)

// Every image box of body i in window w (the box itself first): one box without wrap-around.
std::vector<Aabb> images(const Trajectories& t, std::size_t i, double grow, double w0, double w1) {
  const Aabb box = ccd::truth_window_box(t, i, grow, w0, w1);
  std::vector<Aabb> out;
  if (const ccd::PeriodicBox* pb = t.periodic())
    pb->for_each_image(box, [&](const ccd::ImageShift& s) {
      const Vec3 o = pb->offset(s);
      out.push_back({box.lo + o, box.hi + o});
    });
  else
    out.push_back(box);
  return out;
}

struct Expected {
  std::set<Entry> pairs, statics;
};

// Brute force: all pairs, all windows, all images.
Expected brute_force(const Trajectories& t, const std::vector<double>& grow, const std::vector<Aabb>& polygons,
                     const ccd::TruthCandidates& c) {
  Expected e;
  const auto n = static_cast<std::uint32_t>(t.size());
  for (std::uint32_t w = 0; w < c.windows; ++w) {
    const double w0 = c.window_start(w), w1 = c.window_start(w + 1);
    std::vector<std::vector<Aabb>> boxes;
    for (std::uint32_t i = 0; i < n; ++i) boxes.push_back(images(t, i, grow[i], w0, w1));
    for (std::uint32_t a = 0; a < n; ++a) {
      for (std::uint32_t b = a + 1; b < n; ++b) {
        bool hit = false;
        for (const Aabb& x : boxes[a])
          for (const Aabb& y : boxes[b]) hit = hit || x.overlaps(y);
        if (hit) e.pairs.insert({a, b, w});
      }
      for (std::uint32_t j = 0; j < polygons.size(); ++j)
        if (boxes[a].front().overlaps(polygons[j])) e.statics.insert({a, j, w});
    }
  }
  return e;
}

// The runs expanded to (a, b, window), checking that they are maximal and sorted.
std::set<Entry> expand(const std::vector<ccd::CandidateRun>& runs) {
  std::set<Entry> out;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const ccd::CandidateRun& r = runs[k];
    REQUIRE(r.first_window <= r.last_window);
    if (k > 0) {
      const ccd::CandidateRun& p = runs[k - 1];
      REQUIRE(std::tie(p.a, p.b, p.first_window) < std::tie(r.a, r.b, r.first_window));
      if (p.a == r.a && p.b == r.b) REQUIRE(p.last_window + 1 < r.first_window);  // maximal runs
    }
    for (std::uint32_t w = r.first_window; w <= r.last_window; ++w) out.insert({r.a, r.b, w});
  }
  return out;
}

void require_brute_force(const Scene& s, std::size_t windows, std::size_t expect_at_least) {
  const Trajectories t(s);
  std::vector<double> grow;
  for (std::size_t i = 0; i < t.size(); ++i) grow.push_back(ccd::truth_box_grow(t, i));
  std::vector<Aabb> polygons;
  for (const ccd::StaticPolygon& p : s.scenery) polygons.push_back(ccd::polygon_box(p));
  for (unsigned threads : {1u, 3u}) {
    const ccd::TruthCandidates c = ccd::find_truth_candidates(t, grow, polygons, windows, threads);
    REQUIRE(c.windows == windows);
    const Expected e = brute_force(t, grow, polygons, c);
    REQUIRE(e.pairs.size() + e.statics.size() >= expect_at_least);  // the scene has candidates to find
    CHECK(expand(c.pairs) == e.pairs);
    CHECK(expand(c.statics) == e.statics);
    CHECK(c.pair_windows == e.pairs.size());
    CHECK(c.static_windows == e.statics.size());
  }
}

Scene random_scene(std::uint64_t seed, int n, double offset) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.horizon = 2.0;
  s.gravity = {0, -9.81, 0};
  const double L = 12.0;
  s.box = ccd::WallBox{Vec3::Constant(offset), Vec3::Constant(offset + L)};
  for (int i = 0; i < n; ++i) {
    const double r = i % 7 == 0 ? 1.5 : 0.1 + 0.3 * u(rng);  // a few big bodies among small ones
    Vec3 p, v;
    for (int k = 0; k < 3; ++k) {
      p[k] = offset + r + (L - 2 * r) * u(rng);
      v[k] = 10 * u(rng) - 5;
    }
    s.bodies.push_back(body(r, p, v));
  }
  return s;
}

}  // namespace

TEST_CASE("truth candidates equal brute force on random scenes", "[truth][broad_phase]") {
  for (double offset : {0.0, 1048576.0}) {  // at the origin and at 2^20
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      INFO("offset " << offset << ", seed " << seed);
      const Scene s = random_scene(seed, 60, offset);
      for (std::size_t windows : {std::size_t{1}, std::size_t{5}, std::size_t{13}}) require_brute_force(s, windows, 20);
    }
  }
}

TEST_CASE("truth candidates equal brute force in a box that wraps around", "[truth][broad_phase][periodic]") {
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    INFO("seed " << seed);
    for (std::size_t windows : {std::size_t{1}, std::size_t{6}}) require_brute_force(ccd::test::random_periodic_scene(seed, 80), windows, 20);
  }
}

TEST_CASE("truth candidates with scenery: a floor over every column, small tiles, no polygon pairs",
          "[truth][broad_phase][scenery]") {
  Scene s = random_scene(3, 50, 0.0);
  // A floor that covers the whole box (checked against every box), tiles that overlap it.
  s.scenery.push_back(ccd::polygon_from_vertices({Vec3(0, 0.5, 0), Vec3(12, 0.5, 0), Vec3(12, 0.5, 12), Vec3(0, 0.5, 12)}));
  for (int k = 0; k < 6; ++k) {
    const double x = 2.0 * k;
    s.scenery.push_back(ccd::polygon_from_vertices({Vec3(x, 0.5, 4), Vec3(x + 1, 0.5, 4), Vec3(x + 1, 2.5, 5)}));
  }
  for (std::size_t windows : {std::size_t{1}, std::size_t{7}}) require_brute_force(s, windows, 10);
}

TEST_CASE("truth candidates: exactly touching boxes are candidates, apart by one ulp are not", "[truth][broad_phase]") {
  // Two bodies at rest with grow 1 each (given, not computed): boxes [-1, 1] and [1, 3] on x
  // touch at x = 1 (closed boxes overlap); moving the second by one ulp separates them.
  for (double offset : {0.0, 1048576.0}) {
    INFO("offset " << offset);
    Scene s;
    s.horizon = 1.0;
    s.bodies = {body(0.5, {offset, 0, 0}), body(0.5, {offset + 2.0, 0, 0})};
    const std::vector<double> grow = {1.0, 1.0};
    {
      const Trajectories t(s);
      const ccd::TruthCandidates c = ccd::find_truth_candidates(t, grow, {}, 4, 1);
      REQUIRE(c.pairs.size() == 1);
      CHECK(c.pairs[0] == ccd::CandidateRun{0, 1, 0, 3});  // one run over all four windows
    }
    s.bodies[1].position.x() = std::nextafter(offset + 2.0, 1e300);
    const Trajectories t(s);
    // 1 + ulp: the boxes [offset - 1, offset + 1] and [offset + 1 + ulp, ...] are disjoint
    // (at 2^20 the ulp is 2^-32, and the boxes' ends are exact there).
    CHECK(ccd::find_truth_candidates(t, grow, {}, 4, 1).pairs.empty());
  }
  SECTION("a body on the horizon's last instant only") {
    // Body 1 reaches body 0's box exactly at t = horizon = 1: only the last window.
    Scene s;
    s.horizon = 1.0;
    s.bodies = {body(0.5, {0, 0, 0}), body(0.5, {4, 0, 0}, {-2, 0, 0})};
    const Trajectories t(s);
    const ccd::TruthCandidates c = ccd::find_truth_candidates(t, std::vector<double>{1.0, 1.0}, {}, 4, 1);
    REQUIRE(c.pairs.size() == 1);
    CHECK(c.pairs[0] == ccd::CandidateRun{0, 1, 3, 3});
  }
}

}  // namespace ccd_truth_truth_candidates_test
