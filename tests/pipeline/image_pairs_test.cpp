// The grouping of a wrapped step's image pairs (pipeline/image_pairs.hpp) on hand-made
// local bodies: pairs of a body with its own image dropped, each (a, b, shift) once, body
// pairs once and in order; a body pair passes when any image pair passes, with the least
// `earliest`; its contact is the earliest over its image pairs (the first on a tie).
#include <pipeline/image_pairs.hpp>

#include <catch2/catch.hpp>
#include <vector>

namespace pipeline_image_pairs_test {

namespace {

using ccd::BodyPair;
using ccd::ImageShift;

ccd::ContactResult hit(double toi, double signed_distance) {
  ccd::ContactResult c;
  c.status = ccd::QueryStatus::Hit;
  c.toi = toi;
  c.signed_distance = signed_distance;
  return c;
}

// Bodies 0, 1, 2 and three images: local 3 = body 0 moved by +x, 4 = body 1 moved by +x,
// 5 = body 2 moved by -x.
const std::vector<std::uint32_t> kOwner{0, 1, 2, 0, 1, 2};
const std::vector<ImageShift> kShift{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};

// The broad phase's local pairs (a < b), in no particular order.
const std::vector<BodyPair> kLocal{
    {1, 2},  // (1, 2), shift 0
    {0, 3},  // body 0 and its own image: dropped
    {3, 4},  // (0, 1), shift 0, as {0, 1}: the same image pair, once
    {2, 4},  // (1, 2): 4 is body 1 at +x, so b = 2 relative to a = 1 is at -x
    {0, 1},  // (0, 1), shift 0
    {1, 3},  // (0, 1): 3 is body 0 at +x, so b = 1 relative to a = 0 is at -x
    {2, 5},  // body 2 and its own image: dropped
};

struct Grouped {
  ccd::ImagePairs pairs;
  std::vector<BodyPair> bodies{{7, 9}};  // stale content: overwritten
  Grouped() { pairs.group(kLocal, kOwner, kShift, bodies); }
};

}  // namespace

TEST_CASE("image pairs: each body pair once, each image pair once, own images dropped",
          "[pipeline][periodic]") {
  Grouped g;
  CHECK(g.bodies == std::vector<BodyPair>{{0, 1}, {1, 2}});
  // Sorted by (a, b, shift): the -x image pair before the unshifted one; tested as
  // (min, max) local pairs. The duplicate (0, 1, 0) is kept once, as either local pair.
  const auto tests = g.pairs.tests();
  REQUIRE(tests.size() == 4);
  CHECK(tests[0] == BodyPair{1, 3});
  CHECK((tests[1] == BodyPair{0, 1} || tests[1] == BodyPair{3, 4}));
  CHECK(tests[2] == BodyPair{2, 4});
  CHECK(tests[3] == BodyPair{1, 2});

  SECTION("no local pairs: no body pairs") {
    g.pairs.group({}, kOwner, kShift, g.bodies);
    CHECK(g.bodies.empty());
    CHECK(g.pairs.tests().empty());
  }
}

TEST_CASE("image pairs: passed when any image pair passes, earliest the least", "[pipeline][periodic]") {
  Grouped g;
  const auto tests = g.pairs.tests();
  std::vector<BodyPair> passed;
  std::vector<double> earliest;

  SECTION("both image pairs of (0, 1) and one of (1, 2)") {
    const std::vector<BodyPair> local_passed{tests[0], tests[1], tests[3]};
    const std::vector<double> local_earliest{0.5, 0.25, 0.75};
    g.pairs.reduce_tests(local_passed, local_earliest, passed, earliest);
    CHECK(passed == std::vector<BodyPair>{{0, 1}, {1, 2}});
    CHECK(earliest == std::vector<double>{0.25, 0.75});
    // Solved as (a's local body, b's), each from its own earliest.
    const auto solve = g.pairs.solve();
    REQUIRE(solve.size() == 3);
    CHECK(solve[0] == BodyPair{3, 1});
    CHECK((solve[1] == BodyPair{0, 1} || solve[1] == BodyPair{3, 4}));
    CHECK(solve[2] == BodyPair{1, 2});
    CHECK(std::vector<double>(g.pairs.solve_earliest().begin(), g.pairs.solve_earliest().end()) ==
          std::vector<double>{0.5, 0.25, 0.75});
  }
  SECTION("only the shifted image pair of (1, 2): the body pair passes with its earliest") {
    g.pairs.reduce_tests(std::vector<BodyPair>{tests[2]}, std::vector<double>{0.125}, passed, earliest);
    CHECK(passed == std::vector<BodyPair>{{1, 2}});
    CHECK(earliest == std::vector<double>{0.125});
    REQUIRE(g.pairs.solve().size() == 1);
    CHECK(g.pairs.solve()[0] == BodyPair{4, 2});
  }
  SECTION("none passes: no body pair") {
    g.pairs.reduce_tests({}, {}, passed, earliest);
    CHECK(passed.empty());
    CHECK(earliest.empty());
    CHECK(g.pairs.solve().empty());
  }
}

TEST_CASE("image pairs: a body pair's contact is the earliest over its image pairs", "[pipeline][periodic]") {
  Grouped g;
  const auto tests = g.pairs.tests();
  std::vector<BodyPair> passed;
  std::vector<double> earliest;
  g.pairs.reduce_tests(std::vector<BodyPair>(tests.begin(), tests.end()),
                       std::vector<double>{0.0, 0.0, 0.0, 0.0}, passed, earliest);
  REQUIRE(g.pairs.solve().size() == 4);
  std::vector<std::pair<BodyPair, ccd::ContactResult>> contacts;
  auto collect = [&] {
    contacts.clear();
    g.pairs.for_each_contact(
        [&](const BodyPair& p, const ccd::ContactResult& c) { contacts.emplace_back(p, c); });
  };

  SECTION("the later image pair's contact is earlier: it is kept") {
    g.pairs.keep(0, hit(0.625, -0.5));
    g.pairs.keep(1, hit(0.375, -0.25));
    g.pairs.keep(3, hit(0.5, -0.125));
    collect();
    REQUIRE(contacts.size() == 2);
    CHECK(contacts[0].first == BodyPair{0, 1});
    CHECK(contacts[0].second.toi == 0.375);
    CHECK(contacts[0].second.signed_distance == -0.25);
    CHECK(contacts[1].first == BodyPair{1, 2});
    CHECK(contacts[1].second.toi == 0.5);
  }
  SECTION("a tie keeps the first image pair's contact") {
    g.pairs.keep(0, hit(0.25, -0.5));
    g.pairs.keep(1, hit(0.25, -0.25));
    collect();
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].first == BodyPair{0, 1});
    CHECK(contacts[0].second.signed_distance == -0.5);
  }
  SECTION("only an image pair at t = 0 and the horizon: the earlier one") {
    g.pairs.keep(2, hit(1.0, 0.0));
    g.pairs.keep(3, hit(0.0, -0.0625));
    collect();
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].first == BodyPair{1, 2});
    CHECK(contacts[0].second.toi == 0.0);
  }
  SECTION("no contact found: none reported") {
    collect();
    CHECK(contacts.empty());
  }
}

}  // namespace pipeline_image_pairs_test
