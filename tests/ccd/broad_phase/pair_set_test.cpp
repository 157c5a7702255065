// PairSet against std::set over random inserts and erases: membership, return values,
// the dense list, growth past the initial table and deletions inside probe runs.
#include <ccd/broad_phase/pair_set.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

namespace ccd_broad_phase_pair_set_test {

TEST_CASE("PairSet equals std::set under random inserts and erases", "[broad_phase][sap]") {
  std::mt19937_64 gen(51);
  // Few bodies: many repeated keys, so inserts of members and erases of non-members are
  // frequent; up to ~1200 members: the table grows from 64 slots several times.
  std::uniform_int_distribution<std::uint32_t> body(0, 60);
  std::uniform_int_distribution<int> op(0, 2);
  ccd::PairSet set;
  std::set<std::pair<std::uint32_t, std::uint32_t>> ref;
  for (int step = 0; step < 20000; ++step) {
    std::uint32_t a = body(gen), b = body(gen);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    if (step > 15000 || op(gen) == 0) {  // erase-heavy at the end: the set drains
      REQUIRE(set.erase(a, b) == (ref.erase({a, b}) == 1));
    } else {
      REQUIRE(set.insert(a, b) == ref.insert({a, b}).second);
    }
    REQUIRE(set.contains(a, b) == (ref.count({a, b}) == 1));
    REQUIRE(set.size() == ref.size());
    if (step % 500 == 0) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> got;
      for (const ccd::BodyPair& p : set.pairs()) got.emplace_back(p.a, p.b);
      std::sort(got.begin(), got.end());
      REQUIRE(got == std::vector<std::pair<std::uint32_t, std::uint32_t>>(ref.begin(), ref.end()));
    }
  }
  set.clear();
  CHECK(set.size() == 0u);
  CHECK_FALSE(set.contains(0, 1));
}

}  // namespace ccd_broad_phase_pair_set_test
