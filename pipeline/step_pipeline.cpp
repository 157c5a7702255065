#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow_batch.hpp>
#include <pipeline/step_pipeline.hpp>

#include <algorithm>
#include <chrono>

namespace ccd {
namespace {

using Clock = std::chrono::steady_clock;

// Reads the clock only when timing is wanted.
struct Stopwatch {
  bool on;
  Clock::time_point t0{};
  explicit Stopwatch(bool enabled) : on(enabled) {}
  void start() {
    if (on) t0 = Clock::now();
  }
  void stop(double& into) const {
    if (on) into += std::chrono::duration<double>(Clock::now() - t0).count();
  }
};

// The narrow phase of each of `pairs`, with the entry `entry(a, b)` chooses; found(i, c)
// for each pair i in contact, in order.
template <class Entry, class Found>
void solve_each(NarrowInput in, std::span<const BodyPair> pairs, std::span<const double> earliest, bool from_earliest,
                Entry entry, Found& found) {
  const double t0 = in.t0, t1 = in.t1;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const BodyPair p = pairs[i];
    if (from_earliest) in.t0 = std::max(t0, std::min(earliest[i], t1));
    const ContactResult c = entry(p.a, p.b)(in, p.a, p.b);
    if (c.found()) found(i, c);
  }
}

}  // namespace

StepPipeline::StepPipeline(std::unique_ptr<Bound> bound, Knowledge knowledge, std::unique_ptr<BroadPhase> broad,
                           const NarrowTable& table, PipelineOptions options)
    : bound_(std::move(bound)),
      knowledge_(knowledge),
      options_(options),
      broad_(std::move(broad)),
      table_(&table),
      // Sphere scenes: the one kind pair is looked up once, here.
      narrow_(table.find(ShapeKind::Sphere, ShapeKind::Sphere)) {}

void StepPipeline::run(const StepContext& ctx, StepResult& out, StepTimes* times,
                       std::span<const std::size_t> start_piece) {
  if (ctx.motion->centres().periodic()) {
    if (!images_) images_ = std::make_unique<ImageBodies>();
    run_stages(*images_, ctx, out, times);
  } else {
    PlainBodies plain(start_piece);
    run_stages(plain, ctx, out, times);
  }
}

template <class Bodies>
void StepPipeline::run_stages(Bodies& set, const StepContext& ctx, StepResult& out, StepTimes* times) {
  StepTimes local;
  Stopwatch watch(times != nullptr);
  BodyStage& bs = out.bodies;

  watch.start();
  set.prepare(*bound_, ctx, boxes_);
  watch.stop(local.bound);

  watch.start();
  broad_->find_pairs(boxes_, set.broad_pairs(bs));
  set.candidates(bs);
  watch.stop(local.broad);
  out.broad_stats = broad_->stats();

  watch.start();
  bs.passed.clear();
  bs.earliest.clear();
  std::vector<BodyPair>& passed = set.test_passed(bs);
  std::vector<double>& earliest = set.test_earliest(bs);
  passed.clear();
  earliest.clear();
  bound_->test_pairs(set.test_pairs(bs), passed, earliest);
  set.passed(bs);
  watch.stop(local.bound);

  watch.start();
  bs.contacts.clear();
  const NarrowInput in = set.narrow_input(ctx, sample_test());
  narrow_stage(in, set.narrow_pairs(bs), set.narrow_earliest(bs),
               [&](std::size_t i, const ContactResult& c) { set.found(bs, i, c); });
  set.contacts(bs);
  watch.stop(local.narrow);

  if constexpr (Bodies::kScenery)
    run_static(ctx, in, out, local, times != nullptr);
  else
    out.scenery.clear();

  if (times) {
    times->bound += local.bound;
    times->broad += local.broad;
    times->narrow += local.narrow;
  }
}

template <class Found>
void StepPipeline::narrow_stage(const NarrowInput& in, std::span<const BodyPair> pairs,
                                std::span<const double> earliest, Found found) {
  const RigidMotion& motion = *in.motion;
  const bool from_earliest = options_.narrow_from_earliest && !in.sample;
  // Decided once per step: plain spheres take the sphere x sphere entry looked up once.
  if (motion.spheres() && !from_earliest && !in.sample && narrow_.fn == &sphere_sphere_narrow && !narrow_.swapped) {
    // Sphere scenes, step queries: the batched exact entry (the same results; a SIMD
    // filter settles most pairs, ccd/narrow/sphere_sphere_narrow_batch.hpp).
    batch_results_.resize(pairs.size());
    sphere_sphere_narrow_batch(in, pairs, batch_results_);
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (batch_results_[i].found()) found(i, batch_results_[i]);
  } else if (motion.spheres()) {
    solve_each(in, pairs, earliest, from_earliest, [&](std::uint32_t, std::uint32_t) { return narrow_; }, found);
  } else {
    const auto by_kinds = [&](std::uint32_t a, std::uint32_t b) {
      return table_->find(motion.kind(a), motion.kind(b));
    };
    solve_each(in, pairs, earliest, from_earliest, by_kinds, found);
  }
}

void StepPipeline::set_scenery(std::span<const StaticPolygon> polygons) {
  scenery_ = polygons;
  static_index_ = StaticIndex::from_polygons(polygons);
}

void StepPipeline::run_static(const StepContext& ctx, const NarrowInput& in, StepResult& out, StepTimes& local,
                              bool timed) {
  PairStage<StaticPair, StaticContact>& st = out.scenery;
  st.clear();
  if (scenery_.empty()) return;
  Stopwatch watch(timed);
  const std::size_t n = ctx.start.size();

  watch.start();
  static_index_.find_pairs(std::span<const Aabb>(boxes_.data(), std::min(n, boxes_.size())), st.candidates);
  watch.stop(local.broad);

  watch.start();
  for (const StaticPair& p : st.candidates) {
    const PairTest t = bound_->test_static(p.body, boxes_[p.body], scenery_[p.polygon], static_index_.box(p.polygon));
    if (t.possible()) {
      st.passed.push_back(p);
      st.earliest.push_back(t.earliest);
    }
  }
  watch.stop(local.bound);

  watch.start();
  // The narrow table's polygon column, by the body's kind.
  auto solve = [&](std::uint32_t body, std::uint32_t polygon) {
    return table_->find_polygon(in.motion->kind(body))(in, body, scenery_[polygon]);
  };
  if (!options_.kinematic) {
    for (const StaticPair& p : st.passed) {
      const ContactResult c = solve(p.body, p.polygon);
      if (c.found()) st.contacts.push_back({p, c});
    }
  } else {
    // scenery.passed is sorted by body (the index's order, filtered): one group per body.
    for (std::size_t i = 0; i < st.passed.size();) {
      const std::uint32_t body = st.passed[i].body;
      body_candidates_.clear();
      for (; i < st.passed.size() && st.passed[i].body == body; ++i)
        body_candidates_.push_back({st.passed[i].polygon, st.earliest[i]});
      st.tests_saved += kinematic_visit(
          std::span<StaticCandidate>(body_candidates_), [&](std::uint32_t polygon) { return solve(body, polygon); },
          [&](std::uint32_t polygon, const ContactResult& c) { st.contacts.push_back({{body, polygon}, c}); });
    }
  }
  watch.stop(local.narrow);
}

}  // namespace ccd
