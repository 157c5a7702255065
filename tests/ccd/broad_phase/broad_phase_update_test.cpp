// BroadPhase::update (the scheduler's partial update) for every registry entry: exactly the
// overlapping pairs with at least one moved body, each once with a < b, for small batches
// (the linear path) and large ones (find_pairs, filtered); boxes touching on a face count.
#include <ccd/broad_phase/registry.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

namespace ccd_broad_phase_broad_phase_update_test {

using ccd::Aabb;
using ccd::BodyPair;
using ccd::Vec3;

TEST_CASE("every broad phase's update reports exactly the moved bodies' pairs", "[broad_phase][update]") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u(0.0, 20.0), w(0.1, 1.5);
  const std::uint32_t n = 400;
  std::vector<Aabb> boxes(n);
  for (auto& b : boxes) {
    const Vec3 c(u(rng), u(rng), u(rng));
    b = Aabb::around(c, w(rng));
  }
  for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
    // Equal coordinates: body 1 touches body 0 exactly on a face.
    boxes[0] = {Vec3(0, 0, 0), Vec3(1, 1, 1)};
    boxes[1] = {Vec3(1, 0, 0), Vec3(2, 1, 1)};
    auto broad = info.make();
    std::vector<BodyPair> pairs;
    broad->find_pairs(boxes, pairs);  // a first frame, as the scheduler's
    for (const std::size_t batch : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{n / 4}, std::size_t{n}}) {
      CAPTURE(info.name, batch);
      std::vector<std::uint32_t> all(n);
      for (std::uint32_t i = 0; i < n; ++i) all[i] = i;
      std::shuffle(all.begin(), all.end(), rng);
      std::vector<std::uint32_t> moved(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(batch));
      if (batch == 1) moved[0] = 1;  // the face-touching pair from its second body
      for (const std::uint32_t m : moved) {  // they move
        const Vec3 c(u(rng), u(rng), u(rng));
        if (m != 1) boxes[m] = Aabb::around(c, w(rng));
      }
      broad->update(boxes, moved, pairs);
      const std::set<std::uint32_t> is_moved(moved.begin(), moved.end());
      std::set<BodyPair> expected;
      for (std::uint32_t a = 0; a < n; ++a)
        for (std::uint32_t b = a + 1; b < n; ++b)
          if ((is_moved.count(a) || is_moved.count(b)) && boxes[a].overlaps(boxes[b])) expected.insert({a, b});
      const std::set<BodyPair> got(pairs.begin(), pairs.end());
      CHECK(got.size() == pairs.size());  // each once
      for (const BodyPair& p : pairs) CHECK(p.a < p.b);
      CHECK(got == expected);
      if (batch == 1) CHECK(got.count({0, 1}) == 1);
    }
  }
}

TEST_CASE("every broad phase's update stays exact over a long run of small batches", "[broad_phase][update]") {
  // The scheduler's use: one find_pairs, then many small batches (incremental structures
  // such as grid's hashed cells are kept between them), with a find_pairs and a large batch
  // in between. Adversarial boxes: equal coordinates and shared faces, zero extent (points),
  // boxes much longer than the rest (a bullet's window), far from the origin, moved far
  // outside where the structure was built.
  std::mt19937_64 rng(99);
  const std::uint32_t n = 240;
  std::uniform_real_distribution<double> u(0.0, 16.0), w(0.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 9);
  const auto random_box = [&](double offset) {
    const Vec3 c(std::floor(u(rng)) * 0.5 + offset, std::floor(u(rng)) * 0.5, std::floor(u(rng)) * 0.5);
    switch (kind(rng)) {
      case 0: return Aabb{c, c};                                          // a point
      case 1: return Aabb{c, c + Vec3(64.0, 0.5, 0.5)};                   // long along x
      case 2: return Aabb{c - Vec3(1e6, 0, 0), c - Vec3(1e6 - 1.0, -1, -1)};  // far away
      case 3: return Aabb{c, c + Vec3(1, 1, 1)};                          // unit, on the half grid: shared faces
      default: return Aabb::around(c, w(rng));
    }
  };
  for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
    CAPTURE(info.name);
    std::vector<Aabb> boxes(n);
    for (auto& b : boxes) b = random_box(0.0);
    auto broad = info.make();
    std::vector<BodyPair> pairs;
    broad->find_pairs(boxes, pairs);
    std::uniform_int_distribution<std::uint32_t> body(0, n - 1);
    std::uniform_int_distribution<int> size(1, 12);
    for (int round = 0; round < 120; ++round) {
      CAPTURE(round);
      std::set<std::uint32_t> chosen;
      const int batch = round % 40 == 20 ? static_cast<int>(n / 2) : size(rng);
      while (static_cast<int>(chosen.size()) < batch) chosen.insert(body(rng));
      std::vector<std::uint32_t> moved(chosen.begin(), chosen.end());
      std::shuffle(moved.begin(), moved.end(), rng);
      // Later rounds move bodies away from where the structure was built.
      for (const std::uint32_t m : moved) boxes[m] = random_box(round >= 60 ? 100.0 : 0.0);
      if (round % 30 == 29) {  // a whole frame in between
        broad->find_pairs(boxes, pairs);
        continue;
      }
      broad->update(boxes, moved, pairs);
      std::set<BodyPair> expected;
      for (std::uint32_t a = 0; a < n; ++a)
        for (std::uint32_t b = a + 1; b < n; ++b)
          if ((chosen.count(a) || chosen.count(b)) && boxes[a].overlaps(boxes[b])) expected.insert({a, b});
      const std::set<BodyPair> got(pairs.begin(), pairs.end());
      REQUIRE(got.size() == pairs.size());  // each once
      for (const BodyPair& p : pairs) REQUIRE(p.a < p.b);
      REQUIRE(got == expected);
    }
  }
}

}  // namespace ccd_broad_phase_broad_phase_update_test
