#pragma once
// The one helper that runs indexed work on several threads: the ground truth's windows
// and runs, the experiment's (method, dt) jobs and the grid's body ranges all use it.
//
// parallel_for(count, threads, fn) calls fn(k, worker) exactly once for every k in
// [0, count), on min(threads, count) workers: worker 0 is the calling thread, the others
// are started for the call (std::jthread: tens of microseconds, so callers keep small
// work serial). Items are handed out in increasing k from a shared counter (dynamic: a
// slow item does not hold back the others). Callers must make results depend on k, not
// on the worker (worker indexes per-thread scratch only); then the result does not
// depend on `threads`. threads <= 1 or count <= 1 runs everything on the caller, in order.
// fn must not throw (an exception on a started thread terminates the program).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace ccd {

template <class Fn>
void parallel_for(std::size_t count, unsigned threads, Fn&& fn) {
  if (threads <= 1 || count <= 1) {
    for (std::size_t k = 0; k < count; ++k) fn(k, 0u);
    return;
  }
  const auto workers = static_cast<unsigned>(std::min<std::size_t>(threads, count));
  std::atomic<std::size_t> next{0};
  auto work = [&](unsigned worker) {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) fn(k, worker);
  };
  std::vector<std::jthread> pool;
  pool.reserve(workers - 1);
  for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0u);
}  // the jthreads join here

/// `requested`, or one per hardware core when it is 0 (at least 1).
inline unsigned resolve_threads(unsigned requested) {
  return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace ccd
