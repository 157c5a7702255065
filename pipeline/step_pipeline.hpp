#pragma once
// One step of collision detection as a library call: prepare the bound's boxes -> broad
// phase -> the bound's pair test -> narrow phase, each stage timed. Fixed steps over a
// horizon (pipeline/fixed_step_scheduler.hpp, what the runner runs), the README
// example and kernels_bench all call this.
// docs/architecture.md draws the data path.
//
// A step is [ctx.t0, ctx.t1] (a continuous method: a space-time bound, the narrow phase's
// first contact over the step) or the sample time ctx.t0 == ctx.t1 (a discrete method:
// an Instant bound, the narrow phase's sample test at t0). The bound is given ctx as is;
// the narrow phase gets the same motion, ctx.motion (step queries and sample tests), and
// ctx.start.
// Stages and their outputs (StepResult):
//  1. bound.prepare(ctx) -> one box per body (boxes());
//  2. broad.find_pairs(boxes) -> `bodies.candidates` (a < b, each once);
//  3. bound.test(a, b) for every candidate (through bound.test_pairs) -> `bodies.passed`
//     (status Possible) with `bodies.earliest`, in candidate order;
//  4. narrow table entry for the pair's kinds (sphere x sphere: ccd/narrow/, exact; any
//     other pair: conservative advancement) for every passed pair -> `bodies.contacts` (found:
//     Hit or Overlapping), in passed order. Decided once per step from the motion: when
//     its bodies are plain spheres (RigidMotion::spheres) the one sphere x sphere entry,
//     looked up once, serves every pair, else the entry is looked up per pair by the
//     bodies' kinds. Plain spheres' step queries (without narrow_from_earliest) go through
//     the batched form of the exact entry, ccd/narrow/sphere_sphere_narrow_batch.hpp:
//     same results.
// Scenery (set_scenery: the scene's static polygons, indexed once in a StaticIndex,
// ccd/broad_phase/static_index.hpp), after stage 4 on the same boxes:
//  5. static_index.find_pairs(boxes) -> `scenery.candidates` (body, polygon), by body;
//  6. bound.test_static for each -> `scenery.passed` with `scenery.earliest`;
//  7. the narrow table's polygon column, the entry of the body's kind (the default table:
//     exact for spheres, conservative advancement for other shapes,
//     ccd/narrow/body_polygon_narrow.hpp) for each passed pair
//     -> `scenery.contacts`. With PipelineOptions::kinematic the passed pairs of
//     each body are visited by kinematic_visit (pipeline/kinematic_order.hpp): in order
//     of `earliest`, skipping those that cannot be touched before the body's first certain
//     contact; `scenery.tests_saved` counts the skipped ones. The stages' times add to the
//     broad, bound and narrow times. Bounds see a rigid body as its enclosing sphere
//     (or their own oriented volume); the narrow phase sees its shape. Periodic scenes run
//     no static stages.
// The stages are written once (StepPipeline::run_stages) over a body set
// (pipeline/step_bodies.hpp), which says which pairs each stage works on and how its
// answers come back as body pairs. PlainBodies: the scene's bodies, each candidate its own
// test pair and narrow pair. ImageBodies, for a scene that wraps around
// (`ctx.motion->centres().periodic()`): the bodies and their images are the local bodies
// (pipeline/periodic_images.hpp; the bound is prepared twice when some body has an image),
// the broad phase runs over them, and its pairs are grouped into image pairs (owners and
// relative shift) per body pair (pipeline/image_pairs.hpp). Stage 3 tests every image
// pair (through bound.test_pairs); a body pair passes when any of its image pairs passes,
// `earliest` the least over them. Stage 4 solves every passing image pair (from its own
// `earliest` with narrow_from_earliest) and keeps the earliest contact per body pair. So a
// body pair is reported once in `bodies.candidates`, `bodies.passed` and
// `bodies.contacts`, in order of (a, b). Each image keeps its body's shape and spin (the
// local motion, PeriodicImages::motion), and the narrow entry is chosen as for the bodies
// (plain spheres' step queries batched as above). Periodic scenes run no static stages.
// Stages 3 and 4 run as two passes so that each is timed once per step, not per pair.
// The narrow phase starts at t0 for every pair by default. With
// PipelineOptions::narrow_from_earliest it starts at the pair test's `earliest` instead
// (no contact is possible before it while the bound's assumption holds, so a conservative
// bound finds the same contacts; a bound whose assumption is violated, e.g. |a| > A for a
// horn, may then miss a contact between t0 and `earliest` that the t0 start would find).
#include <bounds/bound.hpp>
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/narrow/narrow_table.hpp>
#include <pipeline/kinematic_order.hpp>
#include <pipeline/pair_stage.hpp>
#include <ccd/broad_phase/static_index.hpp>
#include <pipeline/step_bodies.hpp>
#include <ccd/scene/scenery.hpp>

#include <memory>
#include <vector>

namespace ccd {

/// Seconds spent per stage (steady clock, wall time).
struct StepTimes {
  double bound = 0.0;   ///< prepare + pair tests
  double broad = 0.0;   ///< find_pairs
  double narrow = 0.0;  ///< narrow phase over the passed pairs
};

/// One step's stages for the body pairs and for the body-polygon pairs
/// (pipeline/pair_stage.hpp).
struct StepResult {
  PairStage<BodyPair, PairContact> bodies;       ///< tests_saved stays 0 (no kinematic order)
  PairStage<StaticPair, StaticContact> scenery;  ///< empty without scenery
  BroadPhaseStats broad_stats;                   ///< the broad phase's stats for this step
};

struct PipelineOptions {
  /// false: the narrow phase of every passed pair starts at the step start t0 (default);
  /// true: at the pair test's `earliest` (continuous methods only; a sample test ignores it).
  bool narrow_from_earliest = false;
  /// true: the kinematic principle on the static pairs (pipeline/kinematic_order.hpp);
  /// false: every passed static pair is solved.
  bool kinematic = false;
};

class StepPipeline {
 public:
  /// `knowledge` is the bound's (Instant: sample tests; otherwise step queries).
  StepPipeline(std::unique_ptr<Bound> bound, Knowledge knowledge, std::unique_ptr<BroadPhase> broad,
               const NarrowTable& table = narrow_table(), PipelineOptions options = {});

  /// Runs one step of ctx.motion (the scene's motion, required); `out` is overwritten (its
  /// buffers reused). Adds the stage times to `*times` when given (no clock is read
  /// otherwise). `start_piece` optionally gives each body's piece index at t0 in
  /// ctx.motion->centres() (StateCursor::pieces), sparing the sample test and the narrow
  /// phase a search, and the bound too when it reads ctx.exact (StepContext::start_piece).
  void run(const StepContext& ctx, StepResult& out, StepTimes* times = nullptr,
           std::span<const std::size_t> start_piece = {});

  /// The scenery the steps test the bodies against: indexed once here (the index keeps
  /// the polygons' boxes; the polygons must outlive the pipeline). Empty: no static stages.
  void set_scenery(std::span<const StaticPolygon> polygons);
  const StaticIndex& static_index() const { return static_index_; }

  bool sample_test() const { return knowledge_ == Knowledge::Instant; }
  const Bound& bound() const { return *bound_; }
  const BroadPhase& broad_phase() const { return *broad_; }
  /// The boxes of the last step (one per body; in a periodic scene, one per body and then
  /// one per image, pipeline/periodic_images.hpp).
  const std::vector<Aabb>& boxes() const { return boxes_; }

 private:
  // The stages, written once over a body set (pipeline/step_bodies.hpp): PlainBodies or,
  // for a scene that wraps around, ImageBodies.
  template <class Bodies>
  void run_stages(Bodies& set, const StepContext& ctx, StepResult& out, StepTimes* times);
  // Stage 4 over `pairs` (with their `earliest`): found(i, contact) for each pair i in
  // contact, in order. Decided once per call: plain spheres' step queries go through the
  // batched exact entry, else the narrow table's entries pair by pair (narrow_ for plain
  // spheres, by the pair's kinds otherwise).
  template <class Found>
  void narrow_stage(const NarrowInput& in, std::span<const BodyPair> pairs, std::span<const double> earliest,
                    Found found);
  std::unique_ptr<ImageBodies> images_;  // made by the first step of a scene that wraps around
  std::unique_ptr<Bound> bound_;
  Knowledge knowledge_;
  PipelineOptions options_;
  std::unique_ptr<BroadPhase> broad_;
  const NarrowTable* table_;
  NarrowEntry narrow_;
  std::vector<Aabb> boxes_;
  std::vector<ContactResult> batch_results_;  // the batched narrow phase's answers, per passed pair
  // Scenery.
  void run_static(const StepContext& ctx, const NarrowInput& in, StepResult& out, StepTimes& local, bool timed);
  std::span<const StaticPolygon> scenery_;
  StaticIndex static_index_;
  std::vector<StaticCandidate> body_candidates_;
};

}  // namespace ccd
