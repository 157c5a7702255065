#include <ccd/pipeline/earliest_scheduler.hpp>

#include <bounds/rounding.hpp>
#include <bounds/speed_earliest.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <ccd/narrow/body_polygon_narrow.hpp>
#include <ccd/pipeline/scheduler_images.hpp>
#include <ccd/queries/point_polygon.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace ccd {
namespace {

using Clock = std::chrono::steady_clock;

// Speed-adapted windows are at least dt / 2^10 long.
constexpr int kMaxWindowHalvings = 10;

enum class Kind : std::uint8_t { Check = 0, Expiry = 1 };

// A static check (body a against a polygon of the scenery) carries the polygon in b with
// this bit set, so checks and jobs keep their size; bodies, slots and polygons stay below
// it (run() and set_scenery() refuse more).
constexpr std::uint32_t kStaticBit = 0x80000000u;
constexpr bool is_static(std::uint32_t b) { return (b & kStaticBit) != 0; }
constexpr std::uint32_t static_b(std::uint32_t polygon) { return polygon | kStaticBit; }
constexpr std::uint32_t polygon_of(std::uint32_t b) { return b & ~kStaticBit; }

struct Event {
  double t;
  Kind kind;
  std::uint32_t a, b;    // a pair (a < b; in a wrapped scene two slots, a's owner < b's), or the
                         // expiring body in a (b == a), or a static check's body and static_b(polygon)
  std::uint64_t va, vb;  // the bodies' version stamps when the event was queued
  double since;          // a check: when the bounds it came from start
};

// Min-heap order: earlier first; at equal times checks before expiries, then by bodies
// (a deterministic order, whatever the insertion order).
struct Later {
  bool operator()(const Event& x, const Event& y) const {
    if (x.t != y.t) return x.t > y.t;
    if (x.kind != y.kind) return x.kind > y.kind;
    if (x.a != y.a) return x.a > y.a;
    return x.b > y.b;
  }
};

// A pair check run as soon as it is made (see `inline_checks` in run()).
struct Check {
  double t;
  std::uint32_t a, b;  // as in Event
  double since;        // when the bounds it came from start
  double to;           // the end of the common window
};

// A narrow call over [from, until] in the pair's common window ending at `to`.
struct Job {
  std::uint32_t a, b;
  double from, until, to;
};

// Adds the time since `from` to `into` when timing is on.
struct Watch {
  bool on;
  Clock::time_point from{};
  void start() {
    if (on) from = Clock::now();
  }
  void stop(double& into) const {
    if (on) into += std::chrono::duration<double>(Clock::now() - from).count();
  }
};

}  // namespace

EarliestScheduler::EarliestScheduler(std::unique_ptr<Bound> bound, std::unique_ptr<Bound> scratch,
                                     Knowledge knowledge, std::unique_ptr<BroadPhase> broad,
                                     ScheduleOptions options, const NarrowTable& table)
    : bound_(std::move(bound)),
      scratch_(std::move(scratch)),
      knowledge_(knowledge),
      broad_(std::move(broad)),
      options_(options),
      narrow_(table.find(ShapeKind::Sphere, ShapeKind::Sphere)),
      table_(&table) {
  if (knowledge == Knowledge::Instant)
    throw std::invalid_argument("the earliest scheduler needs a space-time bound (an instant bound has no window)");
  if (!bound_ || !scratch_) throw std::invalid_argument("the earliest scheduler needs two bound instances");
  if (!(options.window > 0.0)) throw std::invalid_argument("the earliest scheduler needs a window dt > 0");
  if (!(options.stale > 0.0 && options.stale <= 1.0))
    throw std::invalid_argument("the earliest scheduler needs stale in (0, 1]");
  if (!(options.reach >= 0.0 && std::isfinite(options.reach)))
    throw std::invalid_argument("the earliest scheduler needs a finite reach >= 0");
  if (!(options.chunk >= 0.0 && std::isfinite(options.chunk)))
    throw std::invalid_argument("the earliest scheduler needs a finite chunk >= 0");
}

void EarliestScheduler::set_scenery(std::span<const StaticPolygon> polygons) {
  if (polygons.size() >= kStaticBit) throw std::invalid_argument("the earliest scheduler takes fewer than 2^31 polygons");
  scenery_ = polygons;
  static_index_ = StaticIndex::from_polygons(polygons);
}

bool EarliestScheduler::run(const Trajectories& motion, double horizon, double acceleration_bound,
                            const std::optional<WallBox>& walls, std::vector<ScheduledContact>& contacts,
                            StepTimes* times, const std::atomic<bool>* cancel) {
  // A wrapped scene: bodies and their images as slots (ccd/pipeline/scheduler_images.hpp).
  const bool wrapped = motion.periodic() != nullptr;
  if (wrapped && options_.rigid)
    throw std::invalid_argument("the earliest scheduler takes plain spheres only in a scene that wraps around");
  if (wrapped && !scenery_.empty())
    throw std::invalid_argument("the earliest scheduler takes no scenery in a scene that wraps around");
  if (motion.size() >= kStaticBit) throw std::invalid_argument("the earliest scheduler takes fewer than 2^31 bodies");
  stats_ = {};
  contacts.clear();
  static_contacts_.clear();
  const std::size_t n = motion.size();
  const double dt = options_.window;
  const double T = horizon;
  const double stale_age = options_.stale * dt;
  const bool refine = options_.stale < 1.0;  // 1: never (a window may exceed dt by rounding)
  StepTimes local;
  Watch watch{times != nullptr};

  std::vector<BodyState> states(n);  // per body (per slot in a wrapped scene)
  // Versions are stamps unique over all bodies and refreshes: a queued event is current while
  // its bodies' stamps are (a slot given to another body then never matches either).
  std::vector<std::uint64_t> version(n, 0);
  std::uint64_t stamp = 0;
  std::vector<Aabb> boxes, scratch_boxes;  // the scratch instance holds refined pairs only (sized at the first)
  std::uint32_t pair_bodies[2];
  std::vector<BodyPair> pairs;
  std::vector<std::uint32_t> batch;
  std::priority_queue<Event, std::vector<Event>, Later> queue;
  // Checks that nothing can invalidate before they are due (no refinement refreshes a
  // body) run as soon as they are made, in rounds: `pending` the round's checks, `next`
  // the checks they give, `jobs` the round's narrow calls. Otherwise checks are queued.
  const bool inline_checks = !options_.refresh_bodies || options_.recheck;
  std::vector<Check> pending, next;
  std::vector<Job> jobs;

  StepContext ctx;
  ctx.acceleration_bound = acceleration_bound;
  ctx.walls = walls;
  ctx.exact = knowledge_ == Knowledge::Exact ? &motion : nullptr;
  ctx.rigid = options_.rigid;
  SchedulerImages images;
  std::vector<BodyState> pair_states(2);
  const std::uint32_t pair_ids[2] = {0, 1};
  if (wrapped) {
    images.begin(motion);
    boxes.resize(n);
    if (ctx.walls) {  // the slots' paths are unwrapped: no walls on a wrapped axis
      constexpr double kInf = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < 3; ++k)
        if (motion.periodic()->wrap[k]) {
          ctx.walls->min[static_cast<int>(k)] = -kInf;
          ctx.walls->max[static_cast<int>(k)] = kInf;
          ctx.walls->boundary[k] = Boundary::Reflect;
        }
    }
  }
  const auto owner = [&](std::uint32_t x) { return wrapped ? images.owner(x) : x; };

  const auto state_at = [&](std::uint32_t i, double t) {
    if (wrapped) {
      states[i] = images.state(i, t);
      return;
    }
    const Piece& q = motion.piece_at(i, t);  // one lookup for both
    states[i] = BodyState{q.position(t), q.velocity(t), motion.radius(i)};
  };
  // Wrapped scenes: the reported slot pairs as image pairs (a < b, relative shift), each once.
  struct ImagePair {
    std::uint32_t a, b;  // bodies
    ImageShift shift;    // of y's image against x's
    std::uint32_t x, y;  // slots (owners a and b)
  };
  std::vector<ImagePair> image_pairs;
  const auto image_pairs_of = [&] {
    image_pairs.clear();
    for (const BodyPair& p : pairs) {
      std::uint32_t x = p.a, y = p.b;
      std::uint32_t a = images.owner(x), b = images.owner(y);
      if (a == SchedulerImages::kFree || b == SchedulerImages::kFree || a == b) continue;
      if (a > b) {
        std::swap(a, b);
        std::swap(x, y);
      }
      image_pairs.push_back({a, b, images.relative(x, y), x, y});
    }
    const auto key = [](const ImagePair& q) { return std::tie(q.a, q.b, q.shift); };
    std::sort(image_pairs.begin(), image_pairs.end(), [&](const ImagePair& p, const ImagePair& q) {
      return key(p) != key(q) ? key(p) < key(q) : std::tie(p.x, p.y) < std::tie(q.x, q.y);
    });
    image_pairs.erase(std::unique(image_pairs.begin(), image_pairs.end(),
                                  [&](const ImagePair& p, const ImagePair& q) { return key(p) == key(q); }),
                      image_pairs.end());
  };
  // Tests the reported pairs and queues a check for each that may touch (not before now).
  const auto test_pairs = [&](double now) {
    if (inline_checks) pending.reserve(pending.size() + (wrapped ? image_pairs.size() : pairs.size()));
    if (wrapped) {
      for (const ImagePair& q : image_pairs) {
        ++stats_.pair_checks;
        const PairTest r = bound_->test(std::min(q.x, q.y), std::max(q.x, q.y));
        if (!r.possible()) continue;
        ++stats_.passed;
        const Window w = common_window(bound_->window(q.x), bound_->window(q.y));
        const double t = std::max(r.earliest, now);
        if (inline_checks) pending.push_back({t, q.x, q.y, w.t0, w.t1});
        else queue.push({t, Kind::Check, q.x, q.y, version[q.a], version[q.b], w.t0});
      }
      return;
    }
    for (const BodyPair& p : pairs) {
      ++stats_.pair_checks;
      const PairTest r = bound_->test(p.a, p.b);
      if (!r.possible()) continue;
      ++stats_.passed;
      const Window w = common_window(bound_->window(p.a), bound_->window(p.b));
      const double t = std::max(r.earliest, now);
      if (inline_checks) pending.push_back({t, p.a, p.b, w.t0, w.t1});
      else queue.push({t, Kind::Check, p.a, p.b, version[p.a], version[p.b], w.t0});
    }
  };
  // Scenery: the static index's polygons for the boxes of `bodies` (bounds just built, from
  // `now`), each tested over the body's own window; a pair that may touch gets a check.
  // Two passes (index, then tests), so that each stage reads the clock once per refresh.
  std::vector<std::uint32_t> polygons;
  std::vector<StaticPair> static_pairs;
  const auto test_static_pairs = [&](double now, std::span<const std::uint32_t> bodies) {
    if (scenery_.empty()) return;
    watch.start();
    static_pairs.clear();
    for (const std::uint32_t i : bodies) {
      polygons.clear();
      static_index_.query(boxes[i], polygons);
      for (const std::uint32_t p : polygons) static_pairs.push_back({i, p});
    }
    watch.stop(local.broad);
    stats_.static_candidates += static_pairs.size();
    watch.start();
    for (const StaticPair& q : static_pairs) {
      const std::uint32_t i = q.body, p = q.polygon;
      ++stats_.static_checks;
      const PairTest r = bound_->test_static(i, boxes[i], scenery_[p], static_index_.box(p));
      if (!r.possible()) continue;
      ++stats_.static_passed;
      const Window w = bound_->window(i);
      const double t = std::max(r.earliest, now);
      if (inline_checks) pending.push_back({t, i, static_b(p), w.t0, w.t1});
      else queue.push({t, Kind::Check, i, static_b(p), version[i], version[i], w.t0});
    }
    watch.stop(local.bound);
  };
  const auto queue_expiry = [&](std::uint32_t i, double w1) {
    if (w1 < T) queue.push({w1, Kind::Expiry, i, i, version[i], version[i], w1});
  };
  // A bound on body i's speed over [t, t1] (state at t set), as the bound's knowledge
  // allows: the exact pieces' largest speed, or |v(t)| + A (t1 - t) (walls keep the speed).
  const auto speed_bound = [&](std::uint32_t i, double t, double t1) {
    if (knowledge_ == Knowledge::Exact) return max_speed(motion, owner(i), t, t1);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    return (states[i].velocity.norm() + acceleration_bound * (t1 - t)) * (1.0 + 8.0 * eps);
  };
  // Speed-adapted windows: the length of body i's window from its state (set at its start).
  double reach_length = 0.0;
  if (options_.reach > 0.0 && n > 0) {
    double radii = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) radii += motion.radius(i);
    reach_length = options_.reach * radii / static_cast<double>(n);
  }
  const auto window_length = [&](std::uint32_t i) {
    double w = dt;
    if (!(reach_length > 0.0)) return w;
    const double v = states[i].velocity.norm();
    for (int k = 0; k < kMaxWindowHalvings && v * w + 0.5 * acceleration_bound * w * w > reach_length; ++k) w *= 0.5;
    return w;
  };
  // The end of body i's window starting at t.
  const auto window_end = [&](std::uint32_t i, double t) {
    const double w = window_length(i);
    double w1 = t + w;
    if (options_.align) {  // the next grid time k w > t (the product, as the fixed steps' times)
      double k = std::floor(t / w) + 1.0;
      while (k > 1.0 && (k - 1.0) * w > t) k -= 1.0;
      while (k * w <= t) k += 1.0;
      w1 = k * w;
    }
    return std::min(w1, T);
  };
  // Rebuilds the bounds of `batch` (states set) from t, each over its own window, one
  // Bound::refresh per distinct window end; sorts `batch` by (end, body) when ends differ.
  std::vector<double> ends(n, 0.0);
  std::vector<std::uint32_t> group;
  const auto build_windows = [&](double t) {
    bool same = true;
    for (const std::uint32_t i : batch) {
      ends[i] = window_end(i, t);
      same = same && ends[i] == ends[batch.front()];
    }
    ctx.t0 = t;
    ctx.start = states;
    if (!same)
      std::sort(batch.begin(), batch.end(),
                [&](std::uint32_t x, std::uint32_t y) { return ends[x] != ends[y] ? ends[x] < ends[y] : x < y; });
    for (std::size_t b = 0; b < batch.size();) {
      std::size_t e = b + 1;
      while (e < batch.size() && ends[batch[e]] == ends[batch[b]]) ++e;
      group.assign(batch.begin() + static_cast<std::ptrdiff_t>(b), batch.begin() + static_cast<std::ptrdiff_t>(e));
      ctx.t1 = ends[batch[b]];
      bound_->refresh(ctx, group, boxes);
      b = e;
    }
  };
  // Refreshes the bodies of `batch` at time t over their next windows.
  const auto refresh = [&](double t) {
    ++stats_.batches;
    stats_.refreshes += batch.size();
    watch.start();
    for (const std::uint32_t i : batch) state_at(i, t);
    build_windows(t);
    watch.stop(local.bound);
    for (const std::uint32_t i : batch) {
      version[i] = ++stamp;
      queue_expiry(i, ends[i]);
    }
    watch.start();
    broad_->update(boxes, batch, pairs);
    watch.stop(local.broad);
    stats_.candidates += pairs.size();
    watch.start();
    test_pairs(t);
    watch.stop(local.bound);
    test_static_pairs(t, batch);
  };

  // Wrapped scenes: refreshes the bodies of `batch` at time t: their home slots, then their
  // images (from the homes' boxes), one Bound::refresh per distinct window end each; the
  // broad phase updates the homes, the images and the slots given back to the pool (or, the
  // first time, finds all pairs).
  std::vector<std::uint32_t> image_slots, freed, moved;
  const auto build_slots = [&](const std::vector<std::uint32_t>& slots, double t) {
    ctx.t0 = t;
    for (std::size_t b = 0; b < slots.size();) {  // slots sorted by their owners' window ends
      const double end = ends[images.owner(slots[b])];
      std::size_t e = b + 1;
      while (e < slots.size() && ends[images.owner(slots[e])] == end) ++e;
      group.assign(slots.begin() + static_cast<std::ptrdiff_t>(b), slots.begin() + static_cast<std::ptrdiff_t>(e));
      ctx.t1 = end;
      const Trajectories& view = images.view(group, t, end);
      ctx.exact = knowledge_ == Knowledge::Exact ? &view : nullptr;
      ctx.start = states;
      bound_->refresh(ctx, group, boxes);
      b = e;
    }
  };
  const auto refresh_wrapped = [&](double t, bool first) {
    ++stats_.batches;
    watch.start();
    for (const std::uint32_t i : batch) {
      images.set_home(i, t);
      state_at(i, t);
      ends[i] = window_end(i, t);
    }
    std::sort(batch.begin(), batch.end(),
              [&](std::uint32_t x, std::uint32_t y) { return ends[x] != ends[y] ? ends[x] < ends[y] : x < y; });
    build_slots(batch, t);
    image_slots.clear();
    freed.clear();
    for (const std::uint32_t i : batch) {
      const Aabb home = boxes[i];  // a copy: set_images may grow `boxes`
      images.set_images(i, home, boxes, image_slots, freed);
    }
    states.resize(images.size());
    for (const std::uint32_t s : image_slots) state_at(s, t);
    build_slots(image_slots, t);
    stats_.refreshes += batch.size() + image_slots.size();
    watch.stop(local.bound);
    for (const std::uint32_t i : batch) {
      version[i] = ++stamp;
      queue_expiry(i, ends[i]);
    }
    watch.start();
    moved.assign(batch.begin(), batch.end());
    moved.insert(moved.end(), image_slots.begin(), image_slots.end());
    moved.insert(moved.end(), freed.begin(), freed.end());
    const std::size_t active = batch.size() + image_slots.size();
    for (std::size_t k = 0; k < active; ++k) images.keep_clear(boxes[moved[k]], boxes, moved);
    if (moved.size() > active + freed.size()) {  // pooled slots re-parked: each once
      std::sort(moved.begin(), moved.end());
      moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    }
    if (first) broad_->find_pairs(boxes, pairs);
    else broad_->update(boxes, moved, pairs);
    watch.stop(local.broad);
    watch.start();
    image_pairs_of();
    stats_.candidates += image_pairs.size();
    test_pairs(t);
    watch.stop(local.bound);
  };

  // Every body's first window [0, min(dt, T)].
  if (wrapped) {
    batch.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) batch[i] = i;
    refresh_wrapped(0.0, true);
  } else {
    watch.start();
    StateCursor(motion).evaluate(0.0, states);  // every body at 0: one pass, no piece search
    ctx.t0 = 0.0;
    ctx.t1 = std::min(dt, T);
    ctx.start = states;
    bound_->prepare(ctx, boxes);
    stats_.refreshes += n;
    std::fill(ends.begin(), ends.end(), ctx.t1);
    if (reach_length > 0.0) {  // bodies with shorter windows: rebuilt over those
      batch.clear();
      for (std::uint32_t i = 0; i < n; ++i)
        if (window_end(i, 0.0) != ctx.t1) batch.push_back(i);
      stats_.refreshes += batch.size();
      if (!batch.empty()) build_windows(0.0);
    }
    watch.stop(local.bound);
    ++stats_.batches;
    watch.start();
    broad_->find_pairs(boxes, pairs);
    watch.stop(local.broad);
    stats_.candidates += pairs.size();
    watch.start();
    test_pairs(0.0);
    watch.stop(local.bound);
    if (!scenery_.empty()) {
      batch.resize(n);
      for (std::uint32_t i = 0; i < n; ++i) batch[i] = i;
      test_static_pairs(0.0, batch);
    }
    for (std::uint32_t i = 0; i < n; ++i) queue_expiry(i, ends[i]);
  }

  // The narrow phase of a check's pair (wrapped: the two slots' paths) over [from, until].
  const auto narrow_pair = [&](std::uint32_t x, std::uint32_t y, double from, double until) {
    const RigidMotion* rigid = options_.rigid;
    if (wrapped) {
      pair_states[0] = states[x];
      pair_states[1] = states[y];
      const NarrowInput in{&images.pair_view(x, y, from, until), pair_states, {}, from, until, false, nullptr};
      return narrow_(in, 0, 1);
    }
    const NarrowInput in{&motion, states, {}, from, until, false, rigid};
    return rigid ? table_->find(rigid->kind(x), rigid->kind(y))(in, x, y) : narrow_(in, x, y);
  };

  // A due static check at c.t (inline mode): body c.a against polygon_of(c.b) over the
  // rest of the body's window, as a pair check below with one moving body.
  const auto decide_static = [&](const Check& c) {
    const double to = c.to;
    const std::uint32_t i = c.a;
    const std::uint32_t p = polygon_of(c.b);
    const StaticPolygon& polygon = scenery_[p];
    if (options_.recheck) {
      // From the body's state now: its distance to the polygon (a static convex set) and
      // its speed bound give the earliest possible contact (bounds/speed_earliest.hpp).
      state_at(i, c.t);
      const Vec3& x = states[i].position;
      const SpeedBall ball{x, c.t, speed_bound(i, c.t, to), states[i].radius};
      const double d = std::sqrt(point_polygon_closest(x, polygon).distance_squared);
      const double from = std::max(c.t, speed_earliest_static(ball, d, static_rounding_slack(x, polygon)));
      ++stats_.static_checks;
      if (from > to) return;
      ++stats_.static_passed;
      // The chunk: the time in which the distance may change by `chunk` x the radius.
      const double h = options_.chunk > 0.0 && ball.speed > 0.0 ? options_.chunk * ball.radius / ball.speed
                                                                  : std::numeric_limits<double>::infinity();
      if (from < to && from >= c.t + h) {
        next.push_back({from, i, c.b, c.since, to});
        return;
      }
      jobs.push_back({i, c.b, from, from + h < to ? from + h : to, to});
      return;
    }
    if (refine && c.t - c.since > stale_age) {
      // The body's own bound from now to the end of its window, in the scratch instance.
      state_at(i, c.t);
      pair_bodies[0] = i;
      ctx.t0 = c.t;
      ctx.t1 = to;
      ctx.start = states;
      if (scratch_boxes.size() != n) scratch_boxes.resize(n);
      scratch_->refresh(ctx, std::span<const std::uint32_t>(pair_bodies, 1), scratch_boxes);
      const PairTest r = scratch_->test_static(i, scratch_boxes[i], polygon, static_index_.box(p));
      ++stats_.refreshes;
      ++stats_.static_checks;
      if (r.possible()) {
        ++stats_.static_passed;
        next.push_back({std::max(r.earliest, c.t), i, c.b, c.t, to});
      }
      return;
    }
    jobs.push_back({i, c.b, c.t, to, to});
  };
  // A due check at c.t (inline mode; c.a, c.b slots when wrapped): the speed re-check or the
  // refinement, which give a later check (into `next`), a narrow call (into `jobs`) or
  // nothing. Reads only the two bodies' bounds and motion, which no refresh changes before
  // the check is due (both windows end at or after c.t).
  const auto decide = [&](const Check& c) {
    if (is_static(c.b)) {
      decide_static(c);
      return;
    }
    const double to = c.to;
    if (options_.recheck) {
      // A speed re-check from both bodies' states now (no bound built), then the narrow
      // phase from its earliest time over one chunk; the pair comes back at the chunk's end.
      state_at(c.a, c.t);
      state_at(c.b, c.t);
      const SpeedBall ba{states[c.a].position, c.t, speed_bound(c.a, c.t, to), states[c.a].radius};
      const SpeedBall bb{states[c.b].position, c.t, speed_bound(c.b, c.t, to), states[c.b].radius};
      const double from = std::max(c.t, speed_earliest(ba, bb));
      ++stats_.pair_checks;
      ++stats_.rechecks;
      if (from > to) return;  // no contact possible in the rest of the common window
      ++stats_.passed;
      // The chunk: the time in which the pair's distance may change by `chunk` x the sum of
      // their radii (at least the rest of the window when neither may move).
      const double closing = ba.speed + bb.speed;
      const double h = options_.chunk > 0.0 && closing > 0.0 ? options_.chunk * (ba.radius + bb.radius) / closing
                                                              : std::numeric_limits<double>::infinity();
      if (from < to && from >= c.t + h) {  // far enough: look again when they may touch
        next.push_back({from, c.a, c.b, c.since, to});
        return;
      }
      jobs.push_back({c.a, c.b, from, from + h < to ? from + h : to, to});
      return;
    }
    if (refine && c.t - c.since > stale_age) {
      // The pair's own bounds from now to the end of the common window.
      state_at(c.a, c.t);
      state_at(c.b, c.t);
      PairTest r;
      if (wrapped) {  // the two slots' paths as bodies 0 and 1 of the scratch instance
        pair_states[0] = states[c.a];
        pair_states[1] = states[c.b];
        const Trajectories& pv = images.pair_view(c.a, c.b, c.t, to);
        StepContext pc = ctx;
        pc.t0 = c.t;
        pc.t1 = to;
        pc.start = pair_states;
        pc.exact = knowledge_ == Knowledge::Exact ? &pv : nullptr;
        if (scratch_boxes.size() < 2) scratch_boxes.resize(2);
        scratch_->refresh(pc, pair_ids, scratch_boxes);
        // Disjoint boxes: the bounds inside them are too (no bound test needed).
        if (scratch_boxes[0].overlaps(scratch_boxes[1])) r = scratch_->test(0, 1);
      } else {
        pair_bodies[0] = c.a;
        pair_bodies[1] = c.b;
        ctx.t0 = c.t;
        ctx.t1 = to;
        ctx.start = states;
        if (scratch_boxes.size() != n) scratch_boxes.resize(n);
        scratch_->refresh(ctx, pair_bodies, scratch_boxes);
        if (scratch_boxes[c.a].overlaps(scratch_boxes[c.b])) r = scratch_->test(c.a, c.b);
      }
      stats_.refreshes += 2;
      ++stats_.pair_checks;
      if (r.possible()) {
        ++stats_.passed;
        next.push_back({std::max(r.earliest, c.t), c.a, c.b, c.t, to});
      }
      return;
    }
    jobs.push_back({c.a, c.b, c.t, to, to});
  };
  // A body's narrow phase against a polygon over [from, until] (exact for a sphere,
  // conservative advancement for another shape).
  const auto narrow_static = [&](std::uint32_t i, std::uint32_t polygon, double from, double until) {
    ++stats_.static_narrow_calls;
    const NarrowInput in{&motion, states, {}, from, until, false, options_.rigid};
    return body_polygon_narrow(in, i, scenery_[polygon]);
  };
  // A narrow call over [from, until]; a found contact is reported over [from, to] and ends
  // the pair's window (as one call over [from, to] would have found it first), else a chunk
  // short of the window's end brings the pair back at its end (into `next`). The same for
  // a static check's (body, polygon) pair and the body's window.
  const auto narrow_job = [&](const Job& j) {
    if (is_static(j.b)) {
      const ContactResult c = narrow_static(j.a, polygon_of(j.b), j.from, j.until);
      if (c.found()) static_contacts_.push_back({{j.a, polygon_of(j.b)}, c, j.from, j.to});
      else if (j.until < j.to) next.push_back({j.until, j.a, j.b, j.from, j.to});
      return;
    }
    ++stats_.narrow_calls;
    const ContactResult c = narrow_pair(j.a, j.b, j.from, j.until);
    if (c.found()) contacts.push_back({{owner(j.a), owner(j.b)}, c, j.from, j.to});
    else if (j.until < j.to) next.push_back({j.until, j.a, j.b, j.from, j.to});  // a re-check (reads no `since`)
  };
  // One round of inline checks: every pending check decided (bound time), then the round's
  // narrow calls (narrow time); what they give is the next round. Two clock reads a stage
  // per round, not per check.
  const auto drain_round = [&] {
    jobs.clear();
    jobs.reserve(pending.size());
    next.reserve(pending.size());
    watch.start();
    for (const Check& c : pending) decide(c);
    watch.stop(local.bound);
    watch.start();
    for (const Job& j : jobs) narrow_job(j);
    watch.stop(local.narrow);
    pending.swap(next);
    next.clear();
  };

  bool finished = true;
  std::uint64_t popped = 0;
  while (!queue.empty() || !pending.empty()) {
    if (!pending.empty()) {  // the checks the last refresh made, in rounds
      if (cancel && cancel->load(std::memory_order_relaxed)) {
        finished = false;
        break;
      }
      drain_round();
      continue;
    }
    if (cancel && (++popped & 1023u) == 0 && cancel->load(std::memory_order_relaxed)) {
      finished = false;
      break;
    }
    const Event e = queue.top();
    queue.pop();
    if (e.kind == Kind::Expiry) {
      if (version[e.a] != e.va) continue;
      batch.assign(1, e.a);
      while (!queue.empty() && queue.top().kind == Kind::Expiry && queue.top().t == e.t) {
        const Event x = queue.top();
        queue.pop();
        if (version[x.a] == x.va) batch.push_back(x.a);
      }
      if (wrapped) refresh_wrapped(e.t, false);
      else refresh(e.t);
      continue;
    }
    // A queued check (refresh_bodies without recheck only): one event at a time, since its
    // refinement refreshes bodies.
    if (is_static(e.b)) {  // a static check: refresh a stale body, else the narrow phase
      if (version[e.a] != e.va) continue;
      const Window w = bound_->window(e.a);
      if (refine && e.t - w.t0 > stale_age) {
        batch.assign(1, e.a);
        refresh(e.t);
        continue;
      }
      watch.start();
      const ContactResult c = narrow_static(e.a, polygon_of(e.b), e.t, w.t1);
      watch.stop(local.narrow);
      if (c.found()) static_contacts_.push_back({{e.a, polygon_of(e.b)}, c, e.t, w.t1});
      continue;
    }
    const std::uint32_t oa = owner(e.a), ob = owner(e.b);  // bodies (e.a, e.b: slots when wrapped)
    if (oa == SchedulerImages::kFree || ob == SchedulerImages::kFree || version[oa] != e.va || version[ob] != e.vb)
      continue;  // queued from an older bound
    const Window wa = bound_->window(e.a);
    const Window wb = bound_->window(e.b);
    batch.clear();
    if (refine && e.t - wa.t0 > stale_age) batch.push_back(oa);
    if (refine && e.t - wb.t0 > stale_age) batch.push_back(ob);
    if (!batch.empty()) {
      if (wrapped) refresh_wrapped(e.t, false);
      else refresh(e.t);
      continue;
    }
    const double to = std::min(wa.t1, wb.t1);
    ++stats_.narrow_calls;
    watch.start();
    const ContactResult c = narrow_pair(e.a, e.b, e.t, to);
    watch.stop(local.narrow);
    if (c.found()) contacts.push_back({{oa, ob}, c, e.t, to});
  }
  if (times) {
    times->bound += local.bound;
    times->broad += local.broad;
    times->narrow += local.narrow;
  }
  return finished;
}

}  // namespace ccd
