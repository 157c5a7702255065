// The benchmarks' list options (benchmarks/support/size_option.hpp): --sizes and --threads
// taken out of the command line, the rest kept in order, bad lists refused.
#include <benchmarks/support/size_option.hpp>

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace benchmarks_support_size_option_test {

namespace {

// argv-like storage for a test command line.
struct Args {
  std::vector<std::string> text;
  std::vector<char*> argv;
  explicit Args(std::vector<std::string> t) : text(std::move(t)) {
    for (std::string& s : text) argv.push_back(s.data());
  }
};

std::vector<std::string> strings(const std::vector<char*>& v) { return {v.begin(), v.end()}; }

}  // namespace

TEST_CASE("the --sizes and --threads options are taken out, the rest kept in order", "[benchmarks]") {
  Args a({"bench", "--benchmark_filter=x", "--threads=1,2,4,8,16", "--sizes=100,2000", "--other"});
  const auto sizes = ccdlab::bench::take_sizes(static_cast<int>(a.argv.size()), a.argv.data(), {5}, "bench", 1000000, "1e6");
  REQUIRE(sizes);
  CHECK(sizes->sizes == std::vector<std::size_t>{100, 2000});
  const auto threads = ccdlab::bench::take_threads(sizes->rest, {1, 2}, "bench");
  REQUIRE(threads);
  CHECK(threads->values == std::vector<std::size_t>{1, 2, 4, 8, 16});
  CHECK(strings(threads->rest) == std::vector<std::string>{"bench", "--benchmark_filter=x", "--other"});
}

TEST_CASE("list options keep their defaults when absent, and the last one given wins", "[benchmarks]") {
  Args a({"bench", "--threads=3", "--threads=7,1"});
  const auto t = ccdlab::bench::take_threads(a.argv, {1, 2}, "bench");
  REQUIRE(t);
  CHECK(t->values == std::vector<std::size_t>{7, 1});
  Args b({"bench"});
  const auto d = ccdlab::bench::take_threads(b.argv, {1, 2}, "bench");
  REQUIRE(d);
  CHECK(d->values == std::vector<std::size_t>{1, 2});
  CHECK(strings(d->rest) == std::vector<std::string>{"bench"});
}

TEST_CASE("bad --threads lists are refused", "[benchmarks]") {
  for (const char* bad : {"--threads=", "--threads=0", "--threads=1,,2", "--threads=2,", "--threads=-1", "--threads=1025",
                          "--threads=two", "--threads=1 2", "--threads=+2"}) {
    CAPTURE(bad);
    Args a({"bench", bad});
    CHECK_FALSE(ccdlab::bench::take_threads(a.argv, {1, 2}, "bench"));
  }
  Args ok({"bench", "--threads=1024,1"});
  CHECK(ccdlab::bench::take_threads(ok.argv, {1, 2}, "bench"));
  // A different option that merely starts alike is not taken.
  Args other({"bench", "--threadsx=3"});
  const auto t = ccdlab::bench::take_threads(other.argv, {1, 2}, "bench");
  REQUIRE(t);
  CHECK(t->values == std::vector<std::size_t>{1, 2});
  CHECK(t->rest.size() == 2);
}

}  // namespace benchmarks_support_size_option_test
