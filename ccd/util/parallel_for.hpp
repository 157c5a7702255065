#pragma once
// The one helper that runs indexed work on several threads: the ground truth's windows
// and runs, the experiment's (method, dt) jobs, the grid's body ranges, the mesh CCD and
// the Python bindings all use it.
//
// parallel_for(count, threads, fn) calls fn(k, worker) exactly once for every k in
// [0, count), on min(threads, count) workers numbered 0, 1, ...: each worker index is in
// use by one thread at a time, so it may index per-thread scratch. Items are handed out in
// increasing k from a shared counter (dynamic: a slow item does not hold back the others;
// callers such as the experiment runner rely on this order). Callers must make results
// depend on k, not on the worker; then the result does not depend on `threads`.
// threads <= 1 or count <= 1 runs everything on the caller, in order.
//
// Engine (parallel_for.cpp): a persistent oneTBB thread pool, one cached task arena per
// thread count (at most `threads` threads in it, the caller being one), so a call costs
// about a microsecond, not the tens of microseconds of starting threads
// (benchmarks/parallel_for_bench.cpp). The workers
// run isolated: while a call waits for its own workers it runs only its own tasks, so
// parallel_for may be nested (an experiment job that runs a threaded grid) without the
// outer call's workers being run on a thread that is inside another outer worker.
// Workers may outnumber the cores (e.g. 16 on 2 cores); a worker's items then run after
// another's on the same thread, so fn must not wait for another item to progress.
//
// Exceptions: if fn throws, no further items are handed out, the items already started
// finish, and the first exception is rethrown on the caller once every worker has ended
// (items with larger k may not have run). The pool stays usable.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <thread>
#include <type_traits>

namespace ccd {

namespace detail {

/// A non-owning reference to a callable fn(std::size_t k, unsigned worker): two words, no
/// allocation; the callable must outlive the reference (it does: the call below).
class IndexedTask {
 public:
  template <class Fn>
  explicit IndexedTask(Fn& fn)
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(fn)))),
        call_([](void* object, std::size_t k, unsigned worker) { (*static_cast<Fn*>(object))(k, worker); }) {}
  void operator()(std::size_t k, unsigned worker) const { call_(object_, k, worker); }

 private:
  void* object_;
  void (*call_)(void*, std::size_t, unsigned);
};

/// Runs task(k, w) for every k in [0, count) on `workers` >= 2 workers of the pool, as
/// parallel_for describes; rethrows the first exception of task.
void run_on_pool(std::size_t count, unsigned workers, IndexedTask task);

}  // namespace detail

template <class Fn>
void parallel_for(std::size_t count, unsigned threads, Fn&& fn) {
  if (threads <= 1 || count <= 1) {
    for (std::size_t k = 0; k < count; ++k) fn(k, 0u);
    return;
  }
  const auto workers = static_cast<unsigned>(std::min<std::size_t>(threads, count));
  detail::run_on_pool(count, workers, detail::IndexedTask(fn));
}

/// `requested`, or one per hardware core when it is 0 (at least 1).
inline unsigned resolve_threads(unsigned requested) {
  return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace ccd
