// The batched sphere x sphere narrow phase against the scalar entry, field for field and
// bit for bit, on scenes with walls (reflections inside and at the ends of steps), shared
// gravity, acceleration changes, touching starts and dyadic data, over steps that start
// at t = 0, end at the horizon, and start exactly at a break.
#include <tests/ccd/scene/body_builder.hpp>

#include <ccd/motion/state_cursor.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow_batch.hpp>

#include <catch2/catch.hpp>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

namespace ccd_narrow_sphere_sphere_narrow_batch_test {

using ccd::Vec3;
using ccd::test::body;

namespace {

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// Every pair i < j of the scene over [t0, t1]: the batch (with and without the cursor's
// pieces) equals the scalar entry. Returns the number of contacts found.
std::size_t check_step(const ccd::Trajectories& m, double t0, double t1) {
  std::vector<ccd::BodyPair> pairs;
  for (std::uint32_t i = 0; i < m.size(); ++i)
    for (std::uint32_t j = i + 1; j < m.size(); ++j) pairs.push_back({i, j});
  std::vector<ccd::BodyState> start;
  ccd::StateCursor cursor(m);
  cursor.evaluate(t0, start);
  const ccd::RigidMotion motion(m);
  std::size_t found = 0;
  for (const bool with_pieces : {false, true}) {
    ccd::NarrowInput in{&motion, start, {}, t0, t1, false};
    if (with_pieces) in.start_piece = cursor.pieces();
    std::vector<ccd::ContactResult> out(pairs.size());
    ccd::sphere_sphere_narrow_batch(in, pairs, out);
    found = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const ccd::ContactResult want = ccd::sphere_sphere_narrow(in, pairs[i].a, pairs[i].b);
      INFO("step [" << t0 << ", " << t1 << "] pair " << pairs[i].a << " " << pairs[i].b);
      REQUIRE(out[i].status == want.status);
      REQUIRE(same_bits(out[i].toi, want.toi));
      REQUIRE(same_bits(out[i].toi_error, want.toi_error));
      REQUIRE(same_bits(out[i].signed_distance, want.signed_distance));
      found += out[i].found();
    }
  }
  return found;
}

}  // namespace

TEST_CASE("batched narrow phase: hand-made dyadic pairs equal the scalar entry", "[narrow][batch]") {
  ccd::Scene s;
  s.horizon = 4.0;
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(16, 16, 16)};
  // 0-1: head-on, touch at t = 1 exactly (gap 2, closing 2), the end of the step [0.5, 1].
  s.bodies.push_back(body(0.5, Vec3(2, 8, 8), Vec3(1, 0, 0)));
  s.bodies.push_back(body(0.5, Vec3(5, 8, 8), Vec3(-1, 0, 0)));
  // 2-3: touching at t = 0 (distance == R), at rest: Overlapping at every step start.
  s.bodies.push_back(body(1, Vec3(8, 2, 2), Vec3::Zero()));
  s.bodies.push_back(body(1, Vec3(10, 2, 2), Vec3::Zero()));
  // 4-5: a tangent pass at t = 2 (closest distance exactly R = 2).
  s.bodies.push_back(body(1, Vec3(8, 12, 12), Vec3::Zero()));
  s.bodies.push_back(body(1, Vec3(10, 14, 12), Vec3(-1, 0, 0)));
  // 6-7: touching at t = 0 (distance 1 = R); 6 reflects off the wall x = 0 at t = 1 (its
  // centre reaches x = r = 0.5) and touches 7 again at t = 2.
  s.bodies.push_back(body(0.5, Vec3(1.5, 4, 12), Vec3(-1, 0, 0)));
  s.bodies.push_back(body(0.5, Vec3(1.5, 5, 12), Vec3::Zero()));
  // 8-9: coincident centres, same velocity (zero relative motion, deep overlap).
  s.bodies.push_back(body(0.75, Vec3(12, 12, 4), Vec3(0.5, 0, 0)));
  s.bodies.push_back(body(0.25, Vec3(12, 12, 4), Vec3(0.5, 0, 0)));
  // 10: an acceleration change at t = 2 (not shared with anyone).
  ccd::Body b = body(0.5, Vec3(12, 4, 4), Vec3(0, 1, 0));
  b.acceleration_changes.push_back({2.0, Vec3(0, 0, 1)});
  s.bodies.push_back(b);
  const ccd::Trajectories m(s);
  std::size_t found = 0;
  for (const auto& [t0, t1] : std::vector<std::pair<double, double>>{
           {0.0, 0.5}, {0.5, 1.0}, {1.0, 1.5}, {0.0, 4.0}, {1.5, 2.0}, {2.0, 2.5}, {3.5, 4.0}, {4.0, 4.0}, {0.75, 0.75}})
    found += check_step(m, t0, t1);
  CHECK(found > 0);
  // The wrong number of results is refused.
  std::vector<ccd::BodyPair> pairs{{0, 1}};
  std::vector<ccd::ContactResult> out(2);
  const ccd::RigidMotion motion(m);
  CHECK_THROWS_AS(ccd::sphere_sphere_narrow_batch({&motion, {}, {}, 0.0, 1.0, false}, pairs, out),
                  std::invalid_argument);
}

TEST_CASE("batched narrow phase: random crowded scenes with walls and gravity equal the scalar entry",
          "[narrow][batch]") {
#ifdef CCDLAB_SANITIZED
  constexpr std::size_t n = 80;
#else
  constexpr std::size_t n = 200;
#endif
  for (const bool gravity : {false, true}) {
    std::mt19937_64 gen(gravity ? 181 : 182);
    std::uniform_real_distribution<double> pos(1, 15), vel(-8, 8), rad(0.3, 1.2);
    ccd::Scene s;
    s.horizon = 1.0;
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(16, 16, 16)};
    if (gravity) s.gravity = Vec3(0, 0, -9.75);
    for (std::size_t i = 0; i < n; ++i) {
      ccd::Body b = body(rad(gen), Vec3(pos(gen), pos(gen), pos(gen)), Vec3(vel(gen), vel(gen), vel(gen)));
      if (i % 16 == 0) b.position = (b.position * 2).array().round() / 2;  // equal coordinates
      if (gravity && i % 10 == 0) b.acceleration = Vec3(1, 0, 0);          // not shared
      s.bodies.push_back(b);
    }
    const ccd::Trajectories m(s);
    std::size_t found = 0;
    for (int k = 0; k < 4; ++k) found += check_step(m, k / 4.0, (k + 1) / 4.0);
    INFO("gravity " << gravity);
    CHECK(found > 0);
  }
}

}  // namespace ccd_narrow_sphere_sphere_narrow_batch_test
