// The calling thread's CPU time: it grows with work done on the thread, not with time
// spent waiting (sleeping) nor with work done on another thread.
#include <ccd/util/thread_cpu_time.hpp>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <thread>

namespace ccd_util_thread_cpu_time_test {

namespace {

// Spins until the calling thread has used `seconds` of CPU time; returns a value that
// depends on the work so that it is not optimised away.
double spin_cpu(double seconds) {
  const double start = ccd::thread_cpu_seconds();
  double x = 1.0;
  while (ccd::thread_cpu_seconds() - start < seconds)
    for (int i = 0; i < 1000; ++i) x = std::sqrt(x + 1.0);
  return x;
}

}  // namespace

TEST_CASE("thread CPU time counts this thread's work, not its waits or other threads' work", "[util]") {
  const double t0 = ccd::thread_cpu_seconds();
  REQUIRE(t0 > 0.0);  // a running thread has used some CPU time

  SECTION("work") {
    CHECK(spin_cpu(0.02) > 1.0);
    CHECK(ccd::thread_cpu_seconds() - t0 >= 0.02);
  }
  SECTION("sleep: 50 ms of waiting costs (almost) no CPU time") {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    CHECK(ccd::thread_cpu_seconds() - t0 < 0.01);
  }
  SECTION("another thread's work is not counted") {
    double other = 0.0;
    std::thread worker([&] { other = spin_cpu(0.05); });
    worker.join();
    CHECK(other > 1.0);
    CHECK(ccd::thread_cpu_seconds() - t0 < 0.02);
  }
}

}  // namespace ccd_util_thread_cpu_time_test
