#include <ccd/truth/truth.hpp>

#include <ccd/broad_phase/static_index.hpp>
#include <ccd/truth/truth_candidates.hpp>
#include <ccd/truth/truth_table.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>

namespace ccd {
namespace {

// Sorts events and their errors together by `order`; counts the grazing ones. Errors are
// dropped when every event is exact (the file then carries no error fields).
template <class Event, class Order>
std::size_t sort_with_errors(std::vector<Event>& events, std::vector<EventError>& errors, Order order) {
  std::vector<std::size_t> index(events.size());
  std::iota(index.begin(), index.end(), std::size_t{0});
  std::sort(index.begin(), index.end(), [&](std::size_t x, std::size_t y) { return order(events[x], events[y]); });
  std::vector<Event> e;
  std::vector<EventError> r;
  e.reserve(events.size());
  r.reserve(events.size());
  std::size_t grazing = 0;
  bool exact = true;
  for (std::size_t i : index) {
    e.push_back(events[i]);
    r.push_back(errors[i]);
    grazing += errors[i].grazing;
    exact = exact && errors[i] == EventError{};
  }
  events = std::move(e);
  errors = exact ? std::vector<EventError>{} : std::move(r);
  return grazing;
}

std::size_t undecided_count(const std::vector<EventError>& errors) {
  return static_cast<std::size_t>(
      std::count_if(errors.begin(), errors.end(), [](const EventError& e) { return e.undecided; }));
}

std::size_t distinct_pairs(const std::vector<ContactEvent>& events) {
  std::vector<std::uint64_t> pairs;
  pairs.reserve(events.size());
  for (const ContactEvent& e : events) pairs.push_back(std::uint64_t{e.a} << 32 | e.b);
  std::sort(pairs.begin(), pairs.end());
  return static_cast<std::size_t>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
}

}  // namespace

Truth compute_truth(const RigidMotion& motion, std::span<const StaticPolygon> scenery, const TruthOptions& options) {
  Truth out;
  const Trajectories& traj = motion.centres();
  const std::size_t n = traj.size();
  out.horizon = traj.horizon();
  out.has_scenery = !scenery.empty();
  const unsigned threads = resolve_threads(options.threads);
  const std::size_t windows =
      options.windows != 0 ? options.windows : automatic_truth_windows(traj, TruthOptions::max_auto_windows);
  out.stats.windows = windows;
  out.stats.threads = threads;

  std::vector<double> grow(n);
  for (std::size_t i = 0; i < n; ++i) grow[i] = truth_box_grow(traj, i);
  std::vector<Aabb> polygon_boxes;
  polygon_boxes.reserve(scenery.size());
  for (const StaticPolygon& p : scenery) polygon_boxes.push_back(polygon_box(p));
  const TruthCandidates cands = find_truth_candidates(traj, grow, polygon_boxes, windows, threads);
  out.stats.candidate_pair_windows = cands.pair_windows;
  out.stats.candidate_runs = cands.pairs.size();
  out.stats.static_candidate_runs = cands.statics.size();

  const TruthTable& table = options.table ? *options.table : truth_table();
  const TruthQuery query{motion, scenery,
                         options.time_tolerance > 0.0 ? options.time_tolerance : std::ldexp(out.horizon, -30),
                         options.max_evaluations};
  // Body pairs first, then body-polygon pairs, in chunks: one chunk per progress call.
  const std::size_t total = cands.pairs.size() + cands.statics.size();
  const std::size_t chunk = std::clamp<std::size_t>(total / (std::size_t{64} * threads), 1, 4096);
  const std::size_t chunks = (total + chunk - 1) / chunk;
  std::vector<TruthEvents> found(chunks);
  std::mutex progress_mutex;
  std::size_t solved = 0;
  bool cancelled = false;
  parallel_for(chunks, threads, [&](std::size_t c, unsigned) {
    const std::size_t end = std::min(total, (c + 1) * chunk);
    for (std::size_t r = c * chunk; r < end; ++r) {
      if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        cancelled = true;
        return;
      }
      if (r < cands.pairs.size()) {
        const CandidateRun& run = cands.pairs[r];
        table.find(motion.kind(run.a), motion.kind(run.b))(query, run.a, run.b, cands.window_start(run.first_window),
                                                          cands.window_start(run.last_window + 1), found[c]);
      } else {
        const CandidateRun& run = cands.statics[r - cands.pairs.size()];
        table.find_polygon(motion.kind(run.a))(query, run.a, run.b, cands.window_start(run.first_window),
                                               cands.window_start(run.last_window + 1), found[c]);
      }
    }
    if (options.progress) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      solved += end - c * chunk;
      options.progress(solved, total);
    }
  });
  out.stats.cancelled = cancelled;
  for (TruthEvents& f : found) {
    out.events.insert(out.events.end(), f.events.begin(), f.events.end());
    out.errors.insert(out.errors.end(), f.errors.begin(), f.errors.end());
    out.static_events.insert(out.static_events.end(), f.static_events.begin(), f.static_events.end());
    out.static_errors.insert(out.static_errors.end(), f.static_errors.begin(), f.static_errors.end());
    out.stats.evaluations += f.evaluations;
    f = TruthEvents{};
  }
  out.stats.grazing = sort_with_errors(out.events, out.errors, event_order);
  out.stats.static_grazing = sort_with_errors(out.static_events, out.static_errors, static_event_order);
  out.stats.pairs_in_contact = distinct_pairs(out.events);
  out.stats.undecided = undecided_count(out.errors);
  out.stats.static_undecided = undecided_count(out.static_errors);
  return out;
}

}  // namespace ccd
