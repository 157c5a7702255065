// Every conservative bound's `earliest` against the exact first contact (pair_first_contact
// on the true motion), for bodies sharing one window (prepare) and for bodies over
// different windows (refresh, as the earliest scheduler leaves them): whenever a pair
// touches inside the common window, the test is Possible and its `earliest` lies in the
// window, no later than the first contact.
#include <bounds/registry.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>

namespace bounds_earliest_test {

using ccd::Vec3;

// Scenes per case: sanitizer builds (about 10x slower) run a third.
#ifdef CCDLAB_SANITIZED
constexpr int kReps = 1;
#else
constexpr int kReps = 6;
#endif

namespace {

// Every conservative space-time bound spec (M = 1, default, 7 for the parameterised ones).
std::vector<ccd::BoundSpec> conservative_specs() {
  std::vector<ccd::BoundSpec> out;
  for (const std::string& s : ccd::test::bound_specs()) {
    ccd::BoundSpec spec = ccd::parse_bound(s);
    if (spec.info->knowledge != ccd::Knowledge::Instant && spec.info->conservative) out.push_back(std::move(spec));
  }
  return out;
}

std::vector<ccd::BodyState> states_at(const ccd::Trajectories& traj, double t) {
  std::vector<ccd::BodyState> s(traj.size());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = {traj.position(i, t), traj.velocity(i, t), traj.radius(i)};
  return s;
}

struct Tally {
  long contacts = 0, failures = 0;
};

// Checks every pair of `st` against the bound's current windows.
void check_pairs(const ccd::test::Step& st, const ccd::Bound& bound, const std::string& what, Tally& tally) {
  const auto n = static_cast<std::uint32_t>(st.traj.size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      const ccd::Window w = ccd::common_window(bound.window(a), bound.window(b));
      const ccd::PairTest r = bound.test(a, b);
      if (w.t0 > w.t1) {  // no common time: nothing can be possible
        if (r.possible() && ++tally.failures <= 5) FAIL_CHECK(what << ": pair " << a << "," << b << " has no common window");
        continue;
      }
      const std::optional<double> first = ccd::pair_first_contact(st.traj, a, b, w.t0, w.t1);
      if (r.possible() && (r.earliest < w.t0 || r.earliest > w.t1)) {
        if (++tally.failures <= 5) FAIL_CHECK(what << ": earliest " << r.earliest << " outside [" << w.t0 << ", " << w.t1 << "]");
      }
      if (!first) continue;
      ++tally.contacts;
      if (!r.possible() || r.earliest > *first) {
        if (++tally.failures <= 5)
          FAIL_CHECK(what << ": pair " << a << "," << b << " first touches at " << *first << " in [" << w.t0 << ", "
                          << w.t1 << "], test " << r.possible() << " earliest " << r.earliest);
      }
    }
  }
}

}  // namespace

TEST_CASE("every conservative bound's earliest is never after the exact first contact", "[bounds][earliest][zero_miss]") {
  const std::vector<ccd::BoundSpec> specs = conservative_specs();
  REQUIRE(specs.size() >= 5);
  std::mt19937_64 rng(1515);
  std::vector<ccd::Aabb> boxes;
  Tally tally;
  // Gas with walls, gravity and acceleration changes; long and short steps.
  for (int rep = 0; rep < kReps; ++rep) {
    const double h = rep % 2 ? 0.25 : 1.0 / 32;
    const ccd::test::Step st = ccd::test::random_gas(rng, 160, h, 2 * h, 30.0, rep != 5, rep % 3 == 0, 2);
    for (const ccd::BoundSpec& spec : specs) {
      auto bound = spec.make();
      bound->prepare(st.context(spec.info->knowledge), boxes);
      check_pairs(st, *bound, std::string(spec.info->name) + " gas", tally);
    }
  }
  // Constructed contacts: tangent at the end, grazing, parallel, coincident, at rest, far
  // from the origin, right after a wall reflection.
  for (int rep = 0; rep < 4; ++rep) {
    const double h = rep % 2 ? 0.5 : 1.0 / 16;
    const ccd::test::ContactBatch cb = rep < 2 ? ccd::test::contact_batch(rng, 60, h, 30.0)
                                               : ccd::test::wall_contact_batch(rng, 60, h, 30.0);
    for (const ccd::BoundSpec& spec : specs) {
      auto bound = spec.make();
      bound->prepare(cb.step.context(spec.info->knowledge), boxes);
      check_pairs(cb.step, *bound, std::string(spec.info->name) + " constructed", tally);
    }
  }
  CHECK(tally.failures == 0);
  CHECK(tally.contacts > 5000 * kReps / 6);
}

TEST_CASE("bounds over different windows compare correctly", "[bounds][earliest][windows][zero_miss]") {
  const std::vector<ccd::BoundSpec> specs = conservative_specs();
  std::mt19937_64 rng(1516);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<ccd::Aabb> boxes, fresh_boxes;
  Tally tally;
  long split_pairs = 0;
  for (int rep = 0; rep < kReps; ++rep) {
    const double h = rep % 2 ? 0.25 : 1.0 / 32;
    // The horizon covers the later windows too.
    const ccd::test::Step st = ccd::test::random_gas(rng, 160, h, 4 * h, 30.0, rep != 5, rep % 3 == 0, 3);
    // Later window starts: a dyadic fraction, a non-dyadic one, and one that shares a
    // single instant with the first window (t0 + h).
    const double shift = rep % 3 == 0 ? 0.25 * h : rep % 3 == 1 ? h / 3 : h;
    const double s0 = h + shift;
    const std::vector<ccd::BodyState> later = states_at(st.traj, s0);
    std::vector<std::uint32_t> moved;
    for (std::uint32_t i = 0; i < st.traj.size(); ++i)
      if (u(rng) < 0.5) moved.push_back(i);
    for (const ccd::BoundSpec& spec : specs) {
      const std::string what = std::string(spec.info->name) + " shift " + std::to_string(shift / h);
      auto bound = spec.make();
      bound->prepare(st.context(spec.info->knowledge), boxes);
      ccd::StepContext ctx = st.context(spec.info->knowledge);
      ctx.t0 = s0;
      ctx.t1 = s0 + h;
      ctx.start = later;
      bound->refresh(ctx, moved, boxes);
      for (const std::uint32_t i : moved) {
        CHECK(bound->window(i).t0 == s0);
        CHECK(bound->window(i).t1 == s0 + h);
      }
      check_pairs(st, *bound, what, tally);
      // Two refreshed bodies: exactly what a prepare over the later window gives.
      auto fresh = spec.make();
      fresh->prepare(ctx, fresh_boxes);
      // ... and what an instance never prepared gives after refreshing the pair alone (the
      // scheduler's scratch instance).
      auto scratch = spec.make();
      std::vector<ccd::Aabb> scratch_boxes(st.traj.size());
      for (std::size_t x = 0; x + 1 < moved.size(); x += 7) {
        const ccd::PairTest r = bound->test(moved[x], moved[x + 1]);
        const ccd::PairTest f = fresh->test(moved[x], moved[x + 1]);
        CHECK(r.status == f.status);
        if (r.possible()) CHECK(r.earliest == f.earliest);
        const std::uint32_t pair[2] = {moved[x], moved[x + 1]};
        scratch->refresh(ctx, pair, scratch_boxes);
        const ccd::PairTest g = scratch->test(pair[0], pair[1]);
        CHECK(g.status == f.status);
        if (g.possible()) CHECK(g.earliest == f.earliest);
        CHECK(boxes[moved[x]].lo == fresh_boxes[moved[x]].lo);
        CHECK(boxes[moved[x]].hi == fresh_boxes[moved[x]].hi);
      }
      split_pairs += static_cast<long>(moved.size() * (st.traj.size() - moved.size()));
    }
  }
  CHECK(tally.failures == 0);
  // Rep 0 alone (h = 1/32, the sanitizer run) holds about 130 contacts; all six about 1000+.
  CHECK(tally.contacts > (kReps == 1 ? 100 : 1000));
  CHECK(split_pairs > 100000 * kReps / 6);
}

TEST_CASE("instant bounds cannot be refreshed", "[bounds][windows]") {
  for (const char* name : {"sphere", "aabb"}) {
    auto bound = ccd::parse_bound(name).make();
    std::vector<ccd::Aabb> boxes(1);
    const std::uint32_t body = 0;
    CHECK_THROWS_AS(bound->refresh({}, std::span<const std::uint32_t>(&body, 1), boxes), std::logic_error);
  }
}

}  // namespace bounds_earliest_test
