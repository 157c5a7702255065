// parallel_for: every index exactly once, worker indices in range and each in use by one
// thread at a time, items handed out in increasing order, serial order when
// single-threaded, nested calls, exceptions carried to the caller, more workers than cores.
#include <ccd/util/parallel_for.hpp>

#include <catch2/catch.hpp>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace ccd_util_parallel_for_test {

namespace {

unsigned workers_for(std::size_t count, unsigned threads) {
  return threads <= 1 || count <= 1 ? 1u : std::min<unsigned>(threads, static_cast<unsigned>(count));
}

// Runs parallel_for(count, threads) and checks every index once, worker indices in range,
// no worker index on two threads at once, and per worker strictly increasing items (the
// shared counter hands them out in increasing order).
void check_calls(std::size_t count, unsigned threads) {
  CAPTURE(count, threads);
  const unsigned workers = workers_for(count, threads);
  std::vector<std::atomic<int>> hits(count);
  std::vector<std::atomic<int>> busy(workers + 1);
  std::vector<std::vector<std::size_t>> seen(workers + 1);
  std::atomic<bool> range_ok{true}, exclusive_ok{true};
  ccd::parallel_for(count, threads, [&](std::size_t k, unsigned w) {
    hits[k].fetch_add(1);
    if (w >= workers) {
      range_ok = false;
      return;
    }
    if (busy[w].fetch_add(1) != 0) exclusive_ok = false;
    seen[w].push_back(k);  // safe: worker w is on one thread at a time (checked above)
    if (k % 64 == 0) std::this_thread::yield();
    busy[w].fetch_sub(1);
  });
  for (std::size_t k = 0; k < count; ++k) REQUIRE(hits[k].load() == 1);
  REQUIRE(range_ok.load());
  REQUIRE(exclusive_ok.load());
  for (const std::vector<std::size_t>& s : seen)
    for (std::size_t i = 1; i < s.size(); ++i) REQUIRE(s[i - 1] < s[i]);
}

}  // namespace

TEST_CASE("parallel_for calls every index exactly once", "[util][threads]") {
  for (std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{5}, std::size_t{1000}})
    for (unsigned threads : {0u, 1u, 2u, 7u, 16u}) check_calls(count, threads);
}

TEST_CASE("parallel_for with more workers than cores: 7 and 16 workers", "[util][threads]") {
  // On a machine with fewer cores some workers run after others on one thread; indices
  // stay in [0, threads), each on one thread at a time, and the call ends.
  for (unsigned threads : {7u, 16u}) check_calls(100000, threads);
}

TEST_CASE("parallel_for hands items out in increasing order", "[util][threads]") {
  // Items come from a shared counter: the items any one worker sees increase (also
  // checked in every check_calls above).
  constexpr std::size_t count = 20000;
  std::vector<std::vector<std::size_t>> seen(2);
  ccd::parallel_for(count, 2, [&](std::size_t k, unsigned w) { seen[w].push_back(k); });
  std::size_t total = 0;
  for (const std::vector<std::size_t>& s : seen) {
    total += s.size();
    for (std::size_t i = 1; i < s.size(); ++i) REQUIRE(s[i - 1] < s[i]);
  }
  CHECK(total == count);
  // With one worker the order is observed exactly.
  std::vector<std::size_t> order;
  ccd::parallel_for(50, 1, [&](std::size_t k, unsigned) { order.push_back(k); });
  for (std::size_t i = 0; i < order.size(); ++i) REQUIRE(order[i] == i);
}

TEST_CASE("parallel_for with one thread runs in order on the caller", "[util][threads]") {
  std::vector<std::size_t> order;
  const auto caller = std::this_thread::get_id();
  ccd::parallel_for(6, 1, [&](std::size_t k, unsigned w) {
    CHECK(w == 0u);
    CHECK(std::this_thread::get_id() == caller);
    order.push_back(k);
  });
  CHECK(order == std::vector<std::size_t>{0, 1, 2, 3, 4, 5});
  CHECK(ccd::resolve_threads(3) == 3u);
  CHECK(ccd::resolve_threads(0) >= 1u);
}

TEST_CASE("parallel_for nests: inner calls inside outer workers", "[util][threads]") {
  // An outer call of 2, 3 and 7 workers whose items each run an inner call of 2 or 4
  // workers (as the runner's jobs run a threaded grid): every (outer, inner) pair once,
  // every worker index in range at both levels.
  for (unsigned outer_threads : {2u, 3u, 7u})
    for (unsigned inner_threads : {2u, 4u}) {
      CAPTURE(outer_threads, inner_threads);
      constexpr std::size_t outer = 24, inner = 300;
      std::vector<std::atomic<int>> hits(outer * inner);
      std::vector<std::atomic<int>> busy(outer_threads);
      std::atomic<bool> ok{true};
      ccd::parallel_for(outer, outer_threads, [&](std::size_t i, unsigned w) {
        if (w >= outer_threads || busy[w].fetch_add(1) != 0) ok = false;
        ccd::parallel_for(inner, inner_threads, [&](std::size_t j, unsigned v) {
          if (v >= inner_threads) ok = false;
          hits[i * inner + j].fetch_add(1);
        });
        if (w < outer_threads) busy[w].fetch_sub(1);
      });
      CHECK(ok.load());
      for (std::size_t k = 0; k < outer * inner; ++k) REQUIRE(hits[k].load() == 1);
    }
}

TEST_CASE("parallel_for carries the first exception to the caller, and the pool stays usable", "[util][threads]") {
  for (unsigned threads : {2u, 7u}) {
    CAPTURE(threads);
    constexpr std::size_t count = 10000000;  // ~0.5 s of items if the throw did not stop them
    std::atomic<std::size_t> ran{0};
    bool caught = false;
    try {
      ccd::parallel_for(count, threads, [&](std::size_t k, unsigned) {
        ran.fetch_add(1);
        if (k == 10) throw std::runtime_error("item 10");
      });
    } catch (const std::runtime_error& e) {
      caught = std::string(e.what()) == "item 10";
    }
    CHECK(caught);
    // No item is handed out after the throw: at most the items already taken ran.
    CHECK(ran.load() < count);
    // Only one of several throwing items is reported, and the call still ends.
    int thrown = 0;
    try {
      ccd::parallel_for(1000, threads, [&](std::size_t k, unsigned) {
        if (k % 3 == 0) throw std::logic_error("every third");
      });
    } catch (const std::logic_error&) {
      ++thrown;
    }
    CHECK(thrown == 1);
    // Then the pool runs a full call as before.
    check_calls(5000, threads);
  }
  // Serial calls let the exception through unchanged (nothing to wait for).
  CHECK_THROWS_AS(ccd::parallel_for(3, 1, [](std::size_t, unsigned) { throw std::out_of_range("x"); }),
                  std::out_of_range);
}

TEST_CASE("parallel_for from several threads at once", "[util][threads]") {
  // Independent callers (e.g. two Python threads) share the pool's arenas.
  std::vector<std::thread> callers;
  std::atomic<bool> ok{true};
  for (int c = 0; c < 3; ++c)
    callers.emplace_back([&] {
      for (int r = 0; r < 20; ++r) {
        std::vector<std::atomic<int>> hits(2000);
        ccd::parallel_for(hits.size(), 2, [&](std::size_t k, unsigned) { hits[k].fetch_add(1); });
        for (const auto& h : hits)
          if (h.load() != 1) ok = false;
      }
    });
  for (std::thread& t : callers) t.join();
  CHECK(ok.load());
}

}  // namespace ccd_util_parallel_for_test
