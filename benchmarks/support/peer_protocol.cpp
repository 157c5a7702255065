#include "peer_protocol.hpp"

#include <benchmarks/support/peer_scene.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <sstream>
#include <vector>

namespace ccdlab::bench {

namespace {

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}

const ccdlab::bench::PeerSceneReference* reference(std::size_t n) {
  for (const auto& r : ccdlab::bench::peer_scene_references())
    if (r.n == n) return &r;
  return nullptr;
}

std::string check(const std::vector<ccd::BodyPair>& pairs, std::size_t n, int frame, std::uint64_t want_pairs,
                  std::uint64_t want_checksum) {
  const std::uint64_t sum = ccdlab::bench::peer_pair_checksum(pairs);
  if (pairs.size() == want_pairs && sum == want_checksum) return {};
  std::ostringstream os;
  os << "N=" << n << " frame " << frame << ": " << pairs.size() << " pairs, checksum " << std::hex << sum
     << "; published " << std::dec << want_pairs << ", " << std::hex << want_checksum;
  return os.str();
}

}  // namespace

PeerRun run_peer_protocol(ccd::BroadPhase& method, std::size_t n) {
  using Clock = std::chrono::steady_clock;
  PeerRun run;
  const ccdlab::bench::PeerSceneReference* ref = reference(n);
  ccdlab::bench::PeerScene scene(n, 1);
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs;
  scene.boxes(boxes);
  const double s0 = thread_cpu_ms();
  method.find_pairs(boxes, pairs);
  run.setup_ms = thread_cpu_ms() - s0;
  if (ref) run.error = check(pairs, n, 0, ref->pairs_0, ref->checksum_0);
  std::vector<double> ms, wall;
  double pair_sum = 0, swap_sum = 0;
  for (int f = 1; f <= kWarmupFrames + kMeasuredFrames; ++f) {
    scene.step();
    scene.boxes(boxes);
    const auto t0 = Clock::now();
    const double c0 = thread_cpu_ms();
    method.find_pairs(boxes, pairs);
    const double c1 = thread_cpu_ms();
    const auto t1 = Clock::now();
    run.max_ms = std::max(run.max_ms, c1 - c0);
    if (f > kWarmupFrames) {
      ms.push_back(c1 - c0);
      wall.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      const ccd::BroadPhaseStats st = method.stats();
      pair_sum += static_cast<double>(pairs.size());
      for (const ccd::Counter& c : method.counters())
        if (c.name == "swaps") swap_sum += static_cast<double>(c.value);
      run.rebuilds += st.rebuilt ? 1 : 0;
    }
  }
  if (ref && run.error.empty()) run.error = check(pairs, n, 22, ref->pairs_22, ref->checksum_22);
  run.median_ms = median(ms);
  run.median_wall_ms = median(wall);
  run.min_ms = *std::min_element(ms.begin(), ms.end());
  run.pairs_per_frame = pair_sum / kMeasuredFrames;
  run.swaps_per_frame = swap_sum / kMeasuredFrames;
  return run;
}

std::string verify_peer_scene(ccd::BroadPhase& method, std::size_t max_n) {
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs;
  for (const auto& ref : ccdlab::bench::peer_scene_references()) {
    if (ref.n > max_n) continue;
    ccdlab::bench::PeerScene scene(ref.n, 1);
    scene.boxes(boxes);
    method.find_pairs(boxes, pairs);
    if (auto e = check(pairs, ref.n, 0, ref.pairs_0, ref.checksum_0); !e.empty()) return e;
    for (int f = 1; f <= 22; ++f) scene.step();
    scene.boxes(boxes);
    method.find_pairs(boxes, pairs);
    if (auto e = check(pairs, ref.n, 22, ref.pairs_22, ref.checksum_22); !e.empty()) return e;
  }
  return {};
}

}  // namespace ccdlab::bench
