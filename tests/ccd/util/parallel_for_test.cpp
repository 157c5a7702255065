// parallel_for: every index exactly once, worker indices in range, serial order when
// single-threaded.
#include <ccd/util/parallel_for.hpp>

#include <catch2/catch.hpp>
#include <atomic>
#include <vector>

namespace ccd_util_parallel_for_test {

TEST_CASE("parallel_for calls every index exactly once", "[util][threads]") {
  for (std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{1000}})
    for (unsigned threads : {0u, 1u, 2u, 7u}) {
      CAPTURE(count, threads);
      std::vector<std::atomic<int>> hits(count);
      std::atomic<bool> worker_ok{true};
      const unsigned workers = threads <= 1 || count <= 1 ? 1u : std::min<unsigned>(threads, unsigned(count));
      ccd::parallel_for(count, threads, [&](std::size_t k, unsigned w) {
        hits[k].fetch_add(1);
        if (w >= workers) worker_ok = false;
      });
      for (std::size_t k = 0; k < count; ++k) REQUIRE(hits[k].load() == 1);
      CHECK(worker_ok.load());
    }
}

TEST_CASE("parallel_for with one thread runs in order on the caller", "[util][threads]") {
  std::vector<std::size_t> order;
  ccd::parallel_for(6, 1, [&](std::size_t k, unsigned w) {
    CHECK(w == 0u);
    order.push_back(k);
  });
  CHECK(order == std::vector<std::size_t>{0, 1, 2, 3, 4, 5});
  CHECK(ccd::resolve_threads(3) == 3u);
  CHECK(ccd::resolve_threads(0) >= 1u);
}

}  // namespace ccd_util_parallel_for_test
