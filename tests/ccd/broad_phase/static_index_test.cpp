// StaticIndex against brute force (every moving box against every polygon box) on random
// and adversarial inputs: touching boxes, equal coordinates, zero-thickness boxes of
// polygons lying in an axis plane, identical boxes, an empty index, leaf sizes.
#include <catch2/catch.hpp>

#include <ccd/broad_phase/static_index.hpp>
#include <tests/ccd/scene/scenery_support.hpp>

#include <algorithm>
#include <random>

namespace ccd_broad_phase_static_index_test {

using namespace ccd;

namespace {

std::vector<StaticPair> brute(std::span<const Aabb> moving, std::span<const Aabb> fixed) {
  std::vector<StaticPair> out;
  for (std::uint32_t b = 0; b < moving.size(); ++b)
    for (std::uint32_t p = 0; p < fixed.size(); ++p)
      if (moving[b].overlaps(fixed[p])) out.push_back({b, p});
  return out;  // already sorted by body, then polygon
}

// Boxes on an integer lattice: many equal coordinates and touching faces.
Aabb lattice_box(std::mt19937_64& rng, int extent, bool flat) {
  std::uniform_int_distribution<int> c(0, extent), s(0, 2);
  Vec3 lo(c(rng), c(rng), c(rng));
  Vec3 size(s(rng), s(rng), s(rng));
  if (flat) size[static_cast<int>(rng() % 3)] = 0.0;  // a polygon in an axis plane
  return {lo, lo + size};
}

}  // namespace

TEST_CASE("StaticIndex: equals brute force", "[broad_phase][scenery]") {
  const std::size_t leaf = GENERATE(std::size_t{1}, std::size_t{4}, std::size_t{16});
  std::mt19937_64 rng(1404 + leaf);
  SECTION("lattice boxes: touching, equal coordinates, zero thickness") {
    for (int round = 0; round < 20; ++round) {
      std::vector<Aabb> fixed, moving;
      const int n = 1 + round * 13;
      for (int i = 0; i < n; ++i) fixed.push_back(lattice_box(rng, 12, i % 2 == 0));
      for (int i = 0; i < 40; ++i) moving.push_back(lattice_box(rng, 12, i % 7 == 0));
      const StaticIndex index(fixed, leaf);
      std::vector<StaticPair> got;
      index.find_pairs(moving, got);
      CHECK(got == brute(moving, fixed));
    }
  }
  SECTION("random polygons' boxes and random moving boxes") {
    std::uniform_real_distribution<double> u(-20.0, 20.0);
    std::vector<StaticPolygon> polygons;
    for (int i = 0; i < 500; ++i) polygons.push_back(ccd::test::random_polygon(rng, Vec3(u(rng), u(rng), u(rng)), 1.5));
    const StaticIndex index = StaticIndex::from_polygons(polygons, leaf);
    std::vector<Aabb> fixed;
    for (const auto& p : polygons) fixed.push_back(polygon_box(p));
    std::vector<Aabb> moving;
    for (int i = 0; i < 300; ++i) {
      const Vec3 c(u(rng), u(rng), u(rng));
      moving.push_back(Aabb::around(c, 0.1 + std::abs(u(rng)) / 8));
    }
    std::vector<StaticPair> got;
    index.find_pairs(moving, got);
    const auto want = brute(moving, fixed);
    CHECK(got == want);
    CHECK(want.size() > 50);
  }
  SECTION("all polygons share one box; a query touching its corner") {
    std::vector<Aabb> fixed(37, Aabb{{0, 0, 0}, {1, 1, 0}});
    const StaticIndex index(fixed, leaf);
    std::vector<std::uint32_t> out;
    index.query({{1, 1, 0}, {2, 2, 2}}, out);
    CHECK(out.size() == 37);
    CHECK(std::is_sorted(out.begin(), out.end()));
    out.clear();
    index.query({{1.0000000000000002, 1, 0}, {2, 2, 2}}, out);
    CHECK(out.empty());
  }
}

TEST_CASE("StaticIndex: empty scenery and polygon_box", "[broad_phase][scenery]") {
  const StaticIndex empty;
  std::vector<StaticPair> got{{1, 2}};
  const Aabb b{{0, 0, 0}, {1, 1, 1}};
  empty.find_pairs(std::span<const Aabb>(&b, 1), got);
  CHECK(got.empty());
  const StaticPolygon tri = ccd::test::make_polygon({{3, -1, 2}, {5, 0, 2}, {4, 2, 2}});
  const Aabb pb = polygon_box(tri);
  CHECK(pb.lo == Vec3(3, -1, 2));
  CHECK(pb.hi == Vec3(5, 2, 2));  // zero thickness in z
}

}  // namespace ccd_broad_phase_static_index_test
