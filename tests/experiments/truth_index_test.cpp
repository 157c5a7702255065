#include <experiments/truth_index.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace experiments_truth_index_test {

using ccd::ContactEvent;

// The reference: every event of each pair (a, b) as stored, from one scan of all events
// into an ordered map (no hashing), each pair's sorted by enter.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> scan(
    const std::vector<ContactEvent>& events) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> out;
  for (std::uint32_t e = 0; e < events.size(); ++e) out[{events[e].a, events[e].b}].push_back(e);
  for (auto& [pair, list] : out)
    std::stable_sort(list.begin(), list.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return events[x].enter < events[y].enter; });
  return out;
}

std::vector<std::uint32_t> lookup(const ccdlab::TruthIndex& index, std::uint32_t a, std::uint32_t b) {
  const auto s = index.of_pair(a, b);
  return {s.begin(), s.end()};
}

TEST_CASE("truth index: no events, every pair is absent", "[experiments][truth_index]") {
  const ccdlab::TruthIndex index(std::vector<ContactEvent>{});
  CHECK(index.events().empty());
  CHECK(index.of_pair(0, 1).empty());
  CHECK(index.of_pair(0, 0).empty());
  CHECK(index.of_pair(0xffffffffu, 0xffffffffu).empty());
}

TEST_CASE("truth index: one pair, its mirror and its neighbours", "[experiments][truth_index]") {
  // Events out of enter order on purpose: of_pair lists them by enter.
  const std::vector<ContactEvent> events{{3, 7, 0.5, 0.6}, {3, 7, 0.125, 0.25}, {3, 7, 0.25, 0.25}};
  const ccdlab::TruthIndex index(events);
  CHECK(lookup(index, 3, 7) == std::vector<std::uint32_t>{1, 2, 0});
  CHECK(index.of_pair(7, 3).empty());  // the pair as stored (a < b), not its mirror
  CHECK(index.of_pair(3, 6).empty());
  CHECK(index.of_pair(3, 8).empty());
  CHECK(index.of_pair(2, 7).empty());
  CHECK(index.of_pair(0, 0).empty());
  // Keys that share the low or the high 32 bits with the stored one.
  CHECK(index.of_pair(0, 7).empty());
  CHECK(index.of_pair(3, 0).empty());
}

TEST_CASE("truth index agrees with a scan over many pairs, many events each", "[experiments][truth_index]") {
  std::mt19937_64 rng(35);
  for (const int bodies : {2, 5, 40, 400}) {
    std::uniform_int_distribution<std::uint32_t> body(0, bodies - 1);
    std::uniform_int_distribution<int> dyadic(0, 1 << 10);
    std::vector<ContactEvent> events;
    // Pairs with 1 to 12 events each (a pair's events interleaved with others'), both
    // orders of some pairs stored (the index keys the pair as given), and repeated enters.
    for (int k = 0; k < 30 * bodies; ++k) {
      std::uint32_t a = body(rng), b = body(rng);
      if (a == b) continue;
      if (a > b && k % 7 != 0) std::swap(a, b);
      const int many = 1 + static_cast<int>(rng() % 12);
      for (int e = 0; e < many; ++e) {
        const double enter = dyadic(rng) / 1024.0;
        events.push_back({a, b, enter, enter + dyadic(rng) / 4096.0});
      }
    }
    std::shuffle(events.begin(), events.end(), rng);
    const ccdlab::TruthIndex index(events);
    REQUIRE(index.events() == events);
    const auto reference = scan(events);
    std::size_t found = 0;
    for (std::uint32_t a = 0; a < static_cast<std::uint32_t>(bodies) + 2; ++a)
      for (std::uint32_t b = 0; b < static_cast<std::uint32_t>(bodies) + 2; ++b) {
        const auto it = reference.find({a, b});
        const std::vector<std::uint32_t> want = it == reference.end() ? std::vector<std::uint32_t>{} : it->second;
        const std::vector<std::uint32_t> got = lookup(index, a, b);
        // Same events, each pair's by enter (ties in any order).
        REQUIRE(got.size() == want.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
          REQUIRE(events[got[i]].a == a);
          REQUIRE(events[got[i]].b == b);
          if (i > 0) REQUIRE(events[got[i - 1]].enter <= events[got[i]].enter);
        }
        std::vector<std::uint32_t> g = got, w = want;
        std::sort(g.begin(), g.end());
        std::sort(w.begin(), w.end());
        REQUIRE(g == w);
        found += got.size();
      }
    CHECK(found == events.size());
  }
}

TEST_CASE("truth index: body ids up to 2^32 - 1", "[experiments][truth_index]") {
  const std::uint32_t top = 0xffffffffu;
  const std::vector<ContactEvent> events{{top - 1, top, 0.0, 1.0}, {0, top, 0.5, 0.5}, {top - 1, top, 0.0, 0.0}};
  const ccdlab::TruthIndex index(events);
  const std::vector<std::uint32_t> high = lookup(index, top - 1, top);
  REQUIRE(high.size() == 2);
  CHECK(std::is_permutation(high.begin(), high.end(), std::vector<std::uint32_t>{0, 2}.begin()));
  CHECK(lookup(index, 0, top) == std::vector<std::uint32_t>{1});
  CHECK(index.of_pair(top, top - 1).empty());
  CHECK(index.of_pair(top, 0).empty());
}

}  // namespace experiments_truth_index_test
