// Registry-wide tests: parsing, containment of random motions in every bound's box, and
// zero misses of every conservative bound on constructed contacts.
#include <bounds/horn_bound.hpp>
#include <bounds/registry.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>

#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace bounds_registry_test {

using ccd::Vec3;

// Random-case counts: Release runs >= 1e6 constructed pairs; sanitizer builds (about 10x
// slower) run 3 % (CCDLAB_SANITIZED, defined for GCC and clang sanitizer builds by
// tests/CMakeLists.txt). Override with -DCCDLAB_BOUNDS_PAIRS=N.
#ifndef CCDLAB_BOUNDS_PAIRS
#ifdef CCDLAB_SANITIZED
#define CCDLAB_BOUNDS_PAIRS 30000
#else
#define CCDLAB_BOUNDS_PAIRS 1000000
#endif
#endif

namespace {

bool box_contains(const ccd::Aabb& box, const Vec3& c, double r) {
  return (box.lo.array() <= c.array() - r).all() && (c.array() + r <= box.hi.array()).all();
}

}  // namespace

TEST_CASE("the bound registry has unique names and consistent entries", "[bounds][registry]") {
  std::set<std::string_view> names;
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    CHECK(names.insert(b.name).second);
    CHECK(!b.description.empty());
    CHECK(b.conservative);  // every bound here is conservative under its knowledge
    for (const ccd::ParameterSpec& p : b.parameters) {
      CHECK(!p.unit.empty());
      CHECK(p.range.contains(p.default_value));
    }
    CHECK(b.make() != nullptr);
  }
  for (const char* n : {"sphere", "aabb", "frame_aabb", "obb", "swept_aabb", "capsule", "horn", "horn_sat",
                        "enclosing_sphere", "obb_sat"})
    CHECK(names.count(n) == 1);
}

TEST_CASE("parse_bound resolves names and parameters", "[bounds][registry]") {
  SECTION("plain name") {
    const ccd::BoundSpec s = ccd::parse_bound("capsule");
    CHECK(s.info->name == "capsule");
    CHECK(s.make() != nullptr);
  }
  SECTION("default parameter") {
    const ccd::BoundSpec s = ccd::parse_bound("horn");
    CHECK(s.options.integer("pieces") == 4);
    CHECK(s.options.to_json() == nlohmann::json{{"pieces", 4}});
  }
  SECTION("explicit parameter, bare or named") {
    CHECK(ccd::parse_bound("horn_sat:7").options.integer("pieces") == 7);
    CHECK(ccd::parse_bound("horn_sat:pieces=7").options.integer("pieces") == 7);
    const auto horn = ccd::parse_bound("horn:3").make();
    CHECK(dynamic_cast<const ccd::HornBound&>(*horn).pieces() == 3);
  }
  SECTION("a bound without options has an empty table") {
    CHECK(ccd::parse_bound("capsule").options.to_json() == nlohmann::json::object());
    CHECK_THROWS_WITH(ccd::parse_bound("capsule:4"), Catch::Contains("it takes none"));
  }
  SECTION("errors") {
    CHECK_THROWS_AS(ccd::parse_bound("hron"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_bound("horn:0"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_bound("horn:-2"), std::invalid_argument);
    CHECK_THROWS_WITH(ccd::parse_bound("horn:2000"), Catch::Contains("pieces") && Catch::Contains("[1, 1024]"));
    CHECK_THROWS_WITH(ccd::parse_bound("horn:pices=2"), Catch::Contains("unknown parameter 'pices'"));
    CHECK_THROWS_AS(ccd::parse_bound("horn:4x"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_bound("horn:"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_bound("capsule:3"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_bound(""), std::invalid_argument);
    try {
      ccd::parse_bound("hron");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("enclosing_sphere") != std::string::npos);  // lists names
    }
  }
}

TEST_CASE("every bound's box contains the body over the step", "[bounds][containment]") {
  const std::string spec = GENERATE(from_range(ccd::test::bound_specs()));
  const ccd::BoundSpec bs = ccd::parse_bound(spec);
  std::mt19937_64 rng(0xC0FFEE ^ std::hash<std::string>{}(spec));
  auto bound = bs.make();
  std::vector<ccd::Aabb> boxes;
  // 16 steps x 500 bodies x (3 step lengths) = 24000 motions per bound, 33 samples each:
  // over the 16 specs, 3.8e5 motions in total.
  long checked = 0, failed = 0;
  for (int rep = 0; rep < 16; ++rep) {
    for (const double h : {1.0 / 240, 1.0 / 30, 0.5}) {
      const bool walls = rep % 4 != 3;
      const double t0 = (rep % 2) * h;  // steps [0, h] and [h, 2h]
      const ccd::test::Step st =
          ccd::test::random_gas(rng, 500, t0, t0 + h, rep % 3 == 0 ? 0.0 : 50.0, walls, rep % 2 == 0, 3);
      const ccd::StepContext ctx = st.context(bs.info->knowledge);
      bound->prepare(ctx, boxes);
      REQUIRE(boxes.size() == st.start.size());
      const int samples = bs.info->knowledge == ccd::Knowledge::Instant ? 1 : 33;
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (int k = 0; k < samples; ++k) {
          const double t = k + 1 == samples ? ctx.t1 : ctx.t0 + (ctx.t1 - ctx.t0) * k / (samples - 1);
          ++checked;
          if (!box_contains(boxes[i], st.traj.position(i, t), st.traj.radius(i))) {
            if (++failed <= 3) FAIL_CHECK(spec << ": body " << i << " leaves its box at t = " << t << " (h = " << h << ")");
          }
        }
      }
    }
  }
  CHECK(failed == 0);
  CHECK(checked > 0);
}

TEST_CASE("no conservative bound misses a constructed contact", "[bounds][zero_miss]") {
  // Ground truth by construction: each pair touches (or overlaps) at a chosen time tc in
  // the step. Every bound must report it: both the box overlap and its own test, and the
  // reported earliest time must not be after tc. The same batches serve every bound spec.
  const std::vector<std::string> specs = ccd::test::bound_specs();
  std::vector<std::unique_ptr<ccd::Bound>> bounds;
  std::vector<ccd::BoundSpec> parsed;
  for (const std::string& s : specs) {
    parsed.push_back(ccd::parse_bound(s));
    bounds.push_back(parsed.back().make());
  }
  std::mt19937_64 rng(20240611);
  constexpr long total = CCDLAB_BOUNDS_PAIRS;
  // Sanitizer runs (3e4 pairs) take five smaller batches, so the wall batch (the fourth) runs.
  constexpr long per_batch = total >= 100000 ? 20000 : total / 5;
  std::vector<ccd::Aabb> boxes;
  long pairs = 0, misses = 0;
  std::map<std::string, long> kinds;
  const double steps[] = {1.0 / 240, 1.0 / 60, 1.0 / 15, 0.5};
  for (long batch = 0; pairs < total; ++batch) {
    const double h = steps[batch % 4];
    const double A = batch % 5 == 0 ? 0.0 : 30.0;
    // Every fifth batch (from the fourth) is of wall contacts, so even the 5 batches of a
    // sanitizer run hold one, with A = 30 and step lengths cycling.
    const ccd::test::ContactBatch cb = batch % 5 == 3 ? ccd::test::wall_contact_batch(rng, per_batch, h, A)
                                                      : ccd::test::contact_batch(rng, per_batch, h, A);
    for (std::size_t b = 0; b < bounds.size(); ++b) {
      if (parsed[b].info->knowledge == ccd::Knowledge::Instant) continue;
      const ccd::StepContext ctx = cb.step.context(parsed[b].info->knowledge);
      bounds[b]->prepare(ctx, boxes);
      for (std::size_t i = 0; i < cb.tc.size(); ++i) {
        const auto a = static_cast<std::uint32_t>(2 * i);
        const bool box_ok = boxes[a].overlaps(boxes[a + 1]);
        const ccd::PairTest test = bounds[b]->test(a, a + 1);
        const bool test_ok = test.possible();
        const double earliest = test.earliest;
        const bool time_ok = earliest <= cb.tc[i];
        if (!(box_ok && test_ok && time_ok)) {
          if (++misses <= 5)
            FAIL_CHECK(specs[b] << " misses a " << cb.kind[i] << " contact at tc = " << cb.tc[i] << " (h = " << h
                                << ", box " << box_ok << ", test " << test_ok << ", earliest " << earliest << ")");
        }
      }
    }
    for (const std::string& k : cb.kind) ++kinds[k];
    pairs += static_cast<long>(cb.tc.size());
  }
  CHECK(misses == 0);
  CHECK(pairs >= total);
  // Every adversarial kind was exercised in quantity.
  for (const char* k : {"generic", "tangent_at_end", "grazing", "parallel", "coincident_start", "zero_velocity",
                        "far", "after_wall_reflection"}) {
    INFO(k);
    CHECK(kinds[k] >= total / 200);
  }
}

TEST_CASE("instant bounds report every pair touching at the sample time", "[bounds][zero_miss]") {
  std::mt19937_64 rng(77);
  long misses = 0;
  for (int batch = 0; batch < 5; ++batch) {
    // Contact at tc in [0, h] with h = 0: every pair touches or overlaps at the sample time.
    const ccd::test::ContactBatch cb = ccd::test::contact_batch(rng, 20000, 0.0, 10.0);
    for (const ccd::BoundInfo& info : ccd::bound_registry()) {
      if (info.knowledge != ccd::Knowledge::Instant) continue;
      auto bound = info.make();
      std::vector<ccd::Aabb> boxes;
      bound->prepare(cb.step.context(ccd::Knowledge::Instant), boxes);
      for (std::size_t i = 0; i < cb.tc.size(); ++i) {
        const auto a = static_cast<std::uint32_t>(2 * i);
        if (!(boxes[a].overlaps(boxes[a + 1]) && bound->test(a, a + 1).possible())) {
          if (++misses <= 5) FAIL_CHECK(info.name << " misses a " << cb.kind[i] << " pair");
        }
      }
    }
  }
  CHECK(misses == 0);
}

TEST_CASE("instant bounds reject separated pairs", "[bounds][registry]") {
  // Two unit spheres 2.5 apart along the diagonal: boxes overlap (gap 2.5/sqrt(3) < 2 per
  // axis), spheres do not. `sphere` must reject, `aabb` must accept (its box is the test).
  ccd::Scene s;
  s.bodies.push_back({1.0, Vec3(0, 0, 0), Vec3::Zero(), Vec3::Zero(), {}});
  s.bodies.push_back({1.0, Vec3::Constant(2.5 / std::sqrt(3.0)), Vec3::Zero(), Vec3::Zero(), {}});
  ccd::test::Step st;
  st.scene = s;
  st.finish(0.0, 0.0);
  std::vector<ccd::Aabb> boxes;
  auto sphere = ccd::parse_bound("sphere").make();
  sphere->prepare(st.context(ccd::Knowledge::Instant), boxes);
  CHECK(boxes[0].overlaps(boxes[1]));
  CHECK(sphere->test(0, 1).status == ccd::PairTest::Status::Disjoint);
  CHECK(sphere->test(0, 1).earliest == std::numeric_limits<double>::infinity());
  auto aabb = ccd::parse_bound("aabb").make();
  aabb->prepare(st.context(ccd::Knowledge::Instant), boxes);
  CHECK(aabb->test(0, 1).status == ccd::PairTest::Status::Possible);
  CHECK(aabb->test(0, 1).earliest == 0.0);  // the sample time: an instant bound carries no timing
}

}  // namespace bounds_registry_test
