// Progress on long runs: the time-left estimate as it is printed.
#include "../../experiments/progress.hpp"

#include <catch2/catch.hpp>

TEST_CASE("progress: durations for the time left", "[progress]") {
  using ccdlab::Progress;
  CHECK(Progress::duration(0.0) == "0s");
  CHECK(Progress::duration(0.2) == "1s");  // rounded up
  CHECK(Progress::duration(42.0) == "42s");
  CHECK(Progress::duration(185.0) == "3m05s");
  CHECK(Progress::duration(3725.0) == "1h02m");
  CHECK(Progress::duration(-5.0) == "0s");
}
