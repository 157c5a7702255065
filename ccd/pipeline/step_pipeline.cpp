#include <ccd/pipeline/step_pipeline.hpp>

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

void StepPipeline::run(const StepContext& ctx, const Trajectories& motion, StepResult& out, StepTimes* times,
                       std::span<const std::size_t> start_piece, const RigidMotion* rigid) {
  StepTimes local;
  Stopwatch watch(times != nullptr);

  watch.start();
  bound_->prepare(ctx, boxes_);
  watch.stop(local.bound);

  watch.start();
  broad_->find_pairs(boxes_, out.candidates);
  watch.stop(local.broad);
  out.broad_stats = broad_->stats();

  watch.start();
  out.passed.clear();
  out.earliest.clear();
  for (const BodyPair& p : out.candidates) {
    const PairTest t = bound_->test(p.a, p.b);
    if (t.possible()) {
      out.passed.push_back(p);
      out.earliest.push_back(t.earliest);
    }
  }
  watch.stop(local.bound);

  watch.start();
  out.contacts.clear();
  NarrowInput in{&motion, ctx.start, start_piece, ctx.t0, ctx.t1, sample_test(), rigid};
  const bool from_earliest = options_.narrow_from_earliest && !sample_test();
  for (std::size_t i = 0; i < out.passed.size(); ++i) {
    const BodyPair p = out.passed[i];
    if (from_earliest) in.t0 = std::max(ctx.t0, std::min(out.earliest[i], ctx.t1));
    // Sphere scenes: the one entry looked up once; rigid scenes: per pair of shape kinds.
    const ContactResult c = rigid ? table_->find(rigid->kind(p.a), rigid->kind(p.b))(in, p.a, p.b) : narrow_(in, p.a, p.b);
    if (c.found()) out.contacts.push_back({p, c});
  }
  watch.stop(local.narrow);

  if (times) {
    times->bound += local.bound;
    times->broad += local.broad;
    times->narrow += local.narrow;
  }
}

}  // namespace ccd
