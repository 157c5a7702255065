#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow_batch.hpp>
#include <pipeline/step_pipeline.hpp>

#include <algorithm>
#include <chrono>
#include <optional>
#include <tuple>

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

// The narrow phase of every passed pair, with the entry `entry(a, b)` chooses.
template <class Entry>
void solve_passed(NarrowInput in, StepResult& out, bool from_earliest, const StepContext& ctx, Entry entry) {
  for (std::size_t i = 0; i < out.bodies.passed.size(); ++i) {
    const BodyPair p = out.bodies.passed[i];
    if (from_earliest) in.t0 = std::max(ctx.t0, std::min(out.bodies.earliest[i], ctx.t1));
    const ContactResult c = entry(p.a, p.b)(in, p.a, p.b);
    if (c.found()) out.bodies.contacts.push_back({p, c});
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
  const RigidMotion& motion = *ctx.motion;
  if (motion.centres().periodic()) {
    out.scenery.clear();
    run_periodic(ctx, out, times);
    return;
  }
  StepTimes local;
  Stopwatch watch(times != nullptr);

  watch.start();
  if (!start_piece.empty() && ctx.start_piece.empty() && ctx.exact == &motion.centres()) {
    // The bounds built from the pieces walk from the cursor's pieces instead of searching.
    StepContext with_pieces = ctx;
    with_pieces.start_piece = start_piece;
    bound_->prepare(with_pieces, boxes_);
  } else {
    bound_->prepare(ctx, boxes_);
  }
  watch.stop(local.bound);

  watch.start();
  broad_->find_pairs(boxes_, out.bodies.candidates);
  watch.stop(local.broad);
  out.broad_stats = broad_->stats();

  watch.start();
  out.bodies.passed.clear();
  out.bodies.earliest.clear();
  bound_->test_pairs(out.bodies.candidates, out.bodies.passed, out.bodies.earliest);
  watch.stop(local.bound);

  watch.start();
  out.bodies.contacts.clear();
  NarrowInput in{&motion, ctx.start, start_piece, ctx.t0, ctx.t1, sample_test()};
  const bool from_earliest = options_.narrow_from_earliest && !sample_test();
  // Decided once per step: plain spheres take the sphere x sphere entry looked up once.
  if (motion.spheres() && !from_earliest && !sample_test() && narrow_.fn == &sphere_sphere_narrow &&
      !narrow_.swapped) {
    // Sphere scenes, step queries: the batched exact entry (the same results; a SIMD
    // filter settles most pairs, ccd/narrow/sphere_sphere_narrow_batch.hpp).
    batch_results_.resize(out.bodies.passed.size());
    sphere_sphere_narrow_batch(in, out.bodies.passed, batch_results_);
    for (std::size_t i = 0; i < out.bodies.passed.size(); ++i)
      if (batch_results_[i].found()) out.bodies.contacts.push_back({out.bodies.passed[i], batch_results_[i]});
  } else {
    narrow_pairs(in, out, from_earliest, ctx);
  }
  watch.stop(local.narrow);

  in.t0 = ctx.t0;
  run_static(ctx, in, out, local, times != nullptr);

  if (times) {
    times->bound += local.bound;
    times->broad += local.broad;
    times->narrow += local.narrow;
  }
}

NarrowEntry StepPipeline::entry(const RigidMotion& motion, std::uint32_t a, std::uint32_t b) const {
  return motion.spheres() ? narrow_ : table_->find(motion.kind(a), motion.kind(b));
}

void StepPipeline::narrow_pairs(const NarrowInput& in, StepResult& out, bool from_earliest,
                                const StepContext& ctx) const {
  const RigidMotion& motion = *in.motion;
  if (motion.spheres()) {
    solve_passed(in, out, from_earliest, ctx, [&](std::uint32_t, std::uint32_t) { return narrow_; });
  } else {
    solve_passed(in, out, from_earliest, ctx,
                 [&](std::uint32_t a, std::uint32_t b) { return table_->find(motion.kind(a), motion.kind(b)); });
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

void StepPipeline::run_periodic(const StepContext& ctx, StepResult& out, StepTimes* times) {
  StepTimes local;
  Stopwatch watch(times != nullptr);
  if (!images_) images_ = std::make_unique<PeriodicImages>();
  PeriodicImages& im = *images_;

  watch.start();
  bound_->prepare(im.begin(ctx), boxes_);
  if (im.add_images(boxes_)) bound_->prepare(im.context(), boxes_);
  watch.stop(local.bound);

  watch.start();
  broad_->find_pairs(boxes_, local_pairs_);
  watch.stop(local.broad);
  out.broad_stats = broad_->stats();

  // Image pairs -> (a, b, relative shift), each once.
  image_pairs_.clear();
  for (const BodyPair& p : local_pairs_) {
    std::uint32_t x = p.a, y = p.b;
    std::uint32_t a = im.owner(x), b = im.owner(y);
    if (a == b) continue;
    if (a > b) {
      std::swap(a, b);
      std::swap(x, y);
    }
    const ImageShift& sx = im.shift(x);
    const ImageShift& sy = im.shift(y);
    image_pairs_.push_back({a, b, ImageShift{sy[0] - sx[0], sy[1] - sx[1], sy[2] - sx[2]}, x, y});
  }
  auto key = [](const ImagePair& q) { return std::tie(q.a, q.b, q.shift); };
  std::sort(image_pairs_.begin(), image_pairs_.end(), [&](const ImagePair& p, const ImagePair& q) { return key(p) < key(q); });
  image_pairs_.erase(std::unique(image_pairs_.begin(), image_pairs_.end(),
                                 [&](const ImagePair& p, const ImagePair& q) { return key(p) == key(q); }),
                     image_pairs_.end());

  PairStage<BodyPair, PairContact>& bs = out.bodies;
  bs.clear();
  // The local bodies' motion: their owners' shapes and spins on the unwrapped paths.
  const RigidMotion& local_motion = im.motion();
  const NarrowInput base{&local_motion, im.context().start, {}, ctx.t0, ctx.t1, sample_test()};
  const bool from_earliest = options_.narrow_from_earliest && !sample_test();
  for (std::size_t i = 0; i < image_pairs_.size();) {
    const std::uint32_t a = image_pairs_[i].a, b = image_pairs_[i].b;
    bs.candidates.push_back({a, b});
    bool passed = false;
    std::optional<ContactResult> best;
    for (; i < image_pairs_.size() && image_pairs_[i].a == a && image_pairs_[i].b == b; ++i) {
      const ImagePair& q = image_pairs_[i];
      watch.start();
      const PairTest t = bound_->test(std::min(q.x, q.y), std::max(q.x, q.y));
      watch.stop(local.bound);
      if (!t.possible()) continue;
      if (!passed) {
        bs.passed.push_back({a, b});
        bs.earliest.push_back(t.earliest);
        passed = true;
      } else {
        bs.earliest.back() = std::min(bs.earliest.back(), t.earliest);
      }
      watch.start();
      NarrowInput in = base;
      if (from_earliest) in.t0 = std::max(ctx.t0, std::min(t.earliest, ctx.t1));
      const ContactResult c = entry(local_motion, q.x, q.y)(in, q.x, q.y);
      watch.stop(local.narrow);
      if (c.found() && (!best || c.toi < best->toi)) best = c;
    }
    if (best) bs.contacts.push_back({BodyPair{a, b}, *best});
  }

  if (times) {
    times->bound += local.bound;
    times->broad += local.broad;
    times->narrow += local.narrow;
  }
}

}  // namespace ccd
