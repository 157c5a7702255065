// The kinematic principle with a certified (not exact) solver: a contact is certain only
// at the far end of its bracket, toi + toi_error, so candidates that may be touched before
// it are still solved; a near miss (infinite error) skips nothing.
#include <pipeline/kinematic_order.hpp>

#include <catch2/catch.hpp>
#include <limits>
#include <map>
#include <vector>

namespace pipeline_kinematic_order_test {

namespace {

ccd::ContactResult hit(double toi, double error) {
  ccd::ContactResult c;
  c.status = ccd::QueryStatus::Hit;
  c.toi = toi;
  c.toi_error = error;
  return c;
}

std::size_t visit(std::vector<ccd::StaticCandidate> cands, const std::map<std::uint32_t, ccd::ContactResult>& results,
                  std::vector<std::uint32_t>& solved) {
  return ccd::kinematic_visit(
      std::span<ccd::StaticCandidate>(cands),
      [&](std::uint32_t p) {
        solved.push_back(p);
        const auto it = results.find(p);
        return it == results.end() ? ccd::ContactResult{} : it->second;
      },
      [](std::uint32_t, const ccd::ContactResult&) {});
}

}  // namespace

TEST_CASE("kinematic_visit: certain at toi + toi_error", "[pipeline][scenery]") {
  const std::vector<ccd::StaticCandidate> cands{{0, 0.125}, {1, 0.375}, {2, 0.75}};
  std::vector<std::uint32_t> solved;
  SECTION("exact contact at 1/4: polygons whose earliest is later are skipped") {
    CHECK(visit(cands, {{0, hit(0.25, 0.0)}}, solved) == 2);
    CHECK(solved == std::vector<std::uint32_t>{0});
  }
  SECTION("bracket [1/4, 1/2]: polygon 1 (earliest 3/8) may come first and is solved, polygon 2 skipped") {
    CHECK(visit(cands, {{0, hit(0.25, 0.25)}}, solved) == 1);
    CHECK(solved == std::vector<std::uint32_t>{0, 1});
  }
  SECTION("a near miss reported with an infinite error skips nothing") {
    CHECK(visit(cands, {{0, hit(0.25, std::numeric_limits<double>::infinity())}}, solved) == 0);
    CHECK(solved == std::vector<std::uint32_t>{0, 1, 2});
  }
}

}  // namespace pipeline_kinematic_order_test
