// The hashed grid behind grid's incremental update: a query visits every body whose box
// overlaps the query box (boxes sharing only a face or a corner, points, boxes far outside
// the cells it was built over, huge coordinates, boxes spanning more than the cell limit),
// and moves keep that true.
#include <ccd/broad_phase/cell_hash.hpp>

#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <vector>

namespace ccd_broad_phase_cell_hash_test {

using ccd::Aabb;
using ccd::Vec3;

namespace {

std::set<std::uint32_t> visited(const ccd::detail::CellHash& hash, const Aabb& box) {
  std::set<std::uint32_t> out;
  hash.visit(box, [&](std::uint32_t j) { out.insert(j); });
  return out;
}

void check_covers(const ccd::detail::CellHash& hash, const std::vector<Aabb>& boxes) {
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const std::set<std::uint32_t> seen = visited(hash, boxes[i]);
    for (std::uint32_t j = 0; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) {
        INFO("query " << i << " misses " << j);
        CHECK(seen.count(j) == 1);
      }
  }
}

}  // namespace

TEST_CASE("cell hash: a query visits every overlapping box, before and after moves", "[broad_phase][cell_hash]") {
  std::vector<Aabb> boxes = {
      {Vec3(0, 0, 0), Vec3(1, 1, 1)},
      {Vec3(1, 0, 0), Vec3(2, 1, 1)},            // shares a face with 0
      {Vec3(2, 1, 1), Vec3(2, 1, 1)},            // a point on 1's corner
      {Vec3(-3, 0, 0), Vec3(100, 0.5, 0.5)},     // spans more than the cell limit
      {Vec3(1e300, 0, 0), Vec3(1e300, 1, 1)},    // far beyond the index range
      {Vec3(1e300, 0.5, 0.5), Vec3(1e300, 2, 2)},  // overlaps 4
      {Vec3(-1e300, -1, -1), Vec3(-1e300, 0, 0)},
      {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5)},  // a point inside 0
  };
  ccd::detail::CellHash hash;
  hash.build(boxes, 1.0);
  REQUIRE(hash.size() == boxes.size());
  check_covers(hash, boxes);
  // Far from where it was built, and back, and a box growing past the limit and shrinking.
  boxes[0] = {Vec3(5000, 5000, 5000), Vec3(5001, 5001, 5001)};
  hash.move(0, boxes[0]);
  boxes[7] = {Vec3(5001, 5001, 5001), Vec3(5001, 5001, 5001)};
  hash.move(7, boxes[7]);
  boxes[3] = {Vec3(0, 0, 0), Vec3(0.25, 0.25, 0.25)};
  hash.move(3, boxes[3]);
  boxes[1] = {Vec3(-50, -50, -50), Vec3(50, 50, 50)};
  hash.move(1, boxes[1]);
  check_covers(hash, boxes);
  CHECK(visited(hash, boxes[0]).count(7) == 1);
  CHECK(visited(hash, boxes[3]).count(1) == 1);
}

TEST_CASE("cell hash: random moves keep every overlap visible", "[broad_phase][cell_hash]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10.0, 10.0), w(0.0, 3.0);
  std::vector<Aabb> boxes(150);
  for (auto& b : boxes) b = Aabb::around(Vec3(u(rng), u(rng), u(rng)), w(rng));
  ccd::detail::CellHash hash;
  hash.build(boxes, 0.75);
  std::uniform_int_distribution<std::uint32_t> body(0, 149);
  for (int k = 0; k < 600; ++k) {
    const std::uint32_t i = body(rng);
    boxes[i] = Aabb::around(Vec3(u(rng), u(rng), u(rng)) * (k < 300 ? 1.0 : 3.0), w(rng));
    hash.move(i, boxes[i]);
  }
  check_covers(hash, boxes);
}

}  // namespace ccd_broad_phase_cell_hash_test
