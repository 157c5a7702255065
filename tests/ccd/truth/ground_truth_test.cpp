#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/pair_contact.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_truth_ground_truth_test {

using ccd::Body;
using ccd::ContactEvent;
using ccd::Scene;
using ccd::Trajectories;
using ccd::Vec3;

namespace {

// A random scene in a box: walls, optional gravity, per-body accelerations and
// acceleration changes, dense enough for many contacts.
Scene random_scene(std::uint64_t seed, int n, bool gravity, bool own_acc, bool changes, double offset) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.horizon = 2.0;
  if (gravity) s.gravity = {0, -9.81, 0};
  const double L = 12.0;
  s.box = ccd::WallBox{Vec3::Constant(offset), Vec3::Constant(offset + L)};
  for (int i = 0; i < n; ++i) {
    Body b;
    b.radius = 0.2 + 0.6 * u(rng);
    for (int k = 0; k < 3; ++k) {
      b.position[k] = offset + b.radius + (L - 2 * b.radius) * u(rng);
      b.velocity[k] = 10 * u(rng) - 5;
      if (own_acc) b.acceleration[k] = 6 * u(rng) - 3;
    }
    if (changes && i % 2 == 0) b.acceleration_changes = {{0.3 + 0.5 * u(rng), Vec3(4 * u(rng) - 2, 3, 0)}};
    s.bodies.push_back(b);
  }
  return s;
}

}  // namespace

TEST_CASE("compute_truth equals the all-pairs reference on random scenes", "[truth]") {
  struct Case {
    const char* name;
    bool gravity, own_acc, changes;
    double offset;
  };
  const Case cases[] = {{"linear with walls", false, false, false, 0.0},
                        {"gravity (shared acceleration)", true, false, false, 0.0},
                        {"different accelerations", true, true, false, 0.0},
                        {"acceleration changes", false, true, true, 0.0},
                        {"far from the origin (1e6)", true, true, true, 1e6}};
  for (const Case& c : cases) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      INFO(c.name << ", seed " << seed);
      const Trajectories t(random_scene(seed, 50, c.gravity, c.own_acc, c.changes, c.offset));
      const std::vector<ContactEvent> ref = ccd::compute_truth_all_pairs(t);
      REQUIRE(ref.size() > 5);  // the scenes are dense: a test that sees no contact proves nothing
      for (unsigned threads : {1u, 3u, 7u}) {  // 7: more workers than most machines' cores
        for (std::size_t windows : {std::size_t{0}, std::size_t{7}, std::size_t{40}}) {
          INFO("threads " << threads << ", windows " << windows);
          ccd::TruthOptions options;
          options.threads = threads;
          options.windows = windows;
          const auto got = ccd::compute_truth(t, options);
          REQUIRE(got == ref);  // bit for bit: the pair solve does not depend on the window
        }
      }
      // Events are sorted, ordered within pairs and inside [0, horizon].
      for (std::size_t i = 0; i < ref.size(); ++i) {
        REQUIRE(ref[i].a < ref[i].b);
        REQUIRE((0.0 <= ref[i].enter && ref[i].enter <= ref[i].exit && ref[i].exit <= t.horizon()));
        if (i > 0) REQUIRE(ccd::event_order(ref[i - 1], ref[i]));
      }
    }
  }
}

TEST_CASE("the reference agrees with dense sampling of the trajectories", "[truth]") {
  // Independent check of pair_contact_intervals: sample every pair's distance (long
  // double from the exact pieces) and compare with the intervals where the verdict is
  // clear by a relative band of 1e-9 (far beyond rounding, far below any real gap).
  const Trajectories t(random_scene(11, 25, true, true, true, 0.0));
  const auto events = ccd::compute_truth_all_pairs(t);
  const int samples = 1500;
  for (std::uint32_t a = 0; a < t.size(); ++a) {
    for (std::uint32_t b = a + 1; b < t.size(); ++b) {
      const long double R = static_cast<long double>(t.radius(a)) + t.radius(b);
      std::vector<ContactEvent> mine;
      for (const ContactEvent& e : events)
        if (e.a == a && e.b == b) mine.push_back(e);
      for (int k = 0; k <= samples; ++k) {
        const double tt = t.horizon() * k / samples;
        const Vec3 pa = t.position(a, tt), pb = t.position(b, tt);
        long double d2 = 0.0L;
        for (int c = 0; c < 3; ++c) {
          const long double d = static_cast<long double>(pb[c]) - pa[c];
          d2 += d * d;
        }
        bool inside = false;
        for (const ContactEvent& e : mine) inside = inside || (e.enter <= tt && tt <= e.exit);
        if (d2 < R * R * (1.0L - 1e-9L)) REQUIRE(inside);
        if (d2 > R * R * (1.0L + 1e-9L)) REQUIRE(!inside);
      }
    }
  }
}

TEST_CASE("compute_truth on tiny and degenerate scenes", "[truth]") {
  Scene s;
  s.horizon = 1.0;
  SECTION("no bodies and one body: no events") {
    CHECK(ccd::compute_truth(Trajectories(s)).empty());
    Body b;
    b.radius = 1.0;
    s.bodies = {b};
    CHECK(ccd::compute_truth(Trajectories(s)).empty());
  }
  SECTION("two resting overlapping bodies: the whole horizon") {
    Body b;
    b.radius = 1.0;
    s.bodies = {b, b};
    const auto e = ccd::compute_truth(Trajectories(s));
    REQUIRE(e.size() == 1);
    CHECK(e[0] == ContactEvent{0, 1, 0.0, 1.0});
  }
  SECTION("a tangent pass is one event with enter == exit") {
    Body a, b;
    a.radius = b.radius = 1.0;
    b.position = {-1, 2, 0};
    b.velocity = {2, 0, 0};
    s.bodies = {a, b};
    const auto e = ccd::compute_truth(Trajectories(s));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == e[0].exit);
    CHECK(e[0].enter == Approx(0.5).margin(1e-9));
  }
}

}  // namespace ccd_truth_ground_truth_test
