// Progress on long runs: the time-left estimate as it is printed.
#include "../../experiments/progress.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace experiments_progress_test {

TEST_CASE("progress: durations for the time left", "[progress]") {
  using ccdlab::Progress;
  CHECK(Progress::duration(0.0) == "0s");
  CHECK(Progress::duration(0.2) == "1s");  // rounded up
  CHECK(Progress::duration(42.0) == "42s");
  CHECK(Progress::duration(185.0) == "3m05s");
  CHECK(Progress::duration(3725.0) == "1h02m");
  CHECK(Progress::duration(-5.0) == "0s");
}

TEST_CASE("progress: the observer sees every job, quiet or not, up to the total", "[progress]") {
  std::vector<std::pair<std::size_t, std::size_t>> seen;
  ccdlab::Progress progress(3, /*quiet=*/true,
                            [&](std::size_t done, std::size_t total) { seen.emplace_back(done, total); });
  progress.phase("ground truth");
  progress.advance("candidate pairs solved", 5, 10);  // not jobs: not observed
  CHECK(seen.empty());
  progress.start_jobs();
  for (int i = 0; i < 3; ++i) progress.done("job");
  progress.finish();
  const std::vector<std::pair<std::size_t, std::size_t>> want{{0, 3}, {1, 3}, {2, 3}, {3, 3}};
  CHECK(seen == want);
}

}  // namespace experiments_progress_test
