#include <ccd/util/parallel_for.hpp>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <memory>
#include <mutex>

namespace ccd::detail {

namespace {

// One arena per worker count, created on first use and kept for the program's life (never
// destroyed: no ordering problem with oneTBB's own teardown at exit). The caller takes the
// arena's reserved slot; up to workers - 1 pool threads join it. Its concurrency is capped
// at the machine's (oneTBB's default): the pool has no more threads to give (and oneTBB
// warns on stderr when asked for more); the surplus workers then run one after another.
tbb::task_arena& arena_for(unsigned workers) {
  static const auto cores = static_cast<unsigned>(std::max(1, tbb::info::default_concurrency()));
  const unsigned concurrency = std::min(workers, cores);
  static std::mutex mutex;
  static auto* arenas = new std::map<unsigned, std::unique_ptr<tbb::task_arena>>();
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<tbb::task_arena>& arena = (*arenas)[concurrency];
  if (!arena) {
    arena = std::make_unique<tbb::task_arena>(static_cast<int>(concurrency), 1);
    arena->initialize();  // here, under the lock, not lazily in two callers' execute() at once
  }
  return *arena;
}

// Whether this thread is running a worker of a call: a nested call then stays in the
// arena it is in (entering a full arena from inside another would have to wait for a
// free slot there).
thread_local bool in_worker = false;

}  // namespace

void run_on_pool(std::size_t count, unsigned workers, IndexedTask task) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  auto work = [&](unsigned worker) {
    const bool outer = in_worker;
    in_worker = true;
    try {
      for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) task(k, worker);
    } catch (...) {
      if (!failed.exchange(true)) error = std::current_exception();
      next.store(count, std::memory_order_relaxed);  // hand out nothing more
    }
    in_worker = outer;
  };
  // Isolated: while waiting, this call's threads run only this call's workers, never a
  // worker of an enclosing call (which would then run in the middle of another of that
  // call's items, on the same thread).
  auto run = [&] {
    tbb::this_task_arena::isolate([&] {
      tbb::task_group group;
      for (unsigned w = 1; w < workers; ++w) group.run([&work, w] { work(w); });
      work(0);
      group.wait();
    });
  };
  if (in_worker)
    run();
  else
    arena_for(workers).execute(run);
  if (error) std::rethrow_exception(error);
}

}  // namespace ccd::detail
