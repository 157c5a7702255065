#pragma once
// The body sets the step pipeline's stages run over (pipeline/step_pipeline.hpp). The
// stages (prepare, broad phase, pair test, narrow phase, scenery) are written once, in
// StepPipeline; a body set says which pairs each stage works on and how its answers
// become the body pairs of the StepResult:
//  - PlainBodies: the scene's bodies. Every candidate is its own test pair and its own
//    narrow pair, so the stages write `bodies` directly (nothing is copied or mapped).
//  - ImageBodies: a scene that wraps around. The bodies and their images are the local
//    bodies (PeriodicImages, pipeline/periodic_images.hpp); the broad phase's local pairs
//    are grouped into image pairs per body pair, tested and solved one by one and reduced
//    to the body pair (ImagePairs, pipeline/image_pairs.hpp). No static stages.
// What a body set `S` gives the stages (`bodies` is the step's StepResult::bodies):
//   S::kScenery                           whether the static stages run after the narrow phase;
//   prepare(bound, ctx, boxes)            the bound prepared over its bodies, their boxes;
//   broad_pairs(bodies)                   where the broad phase writes its pairs;
//   candidates(bodies)                    from those, bodies.candidates;
//   test_pairs(bodies), test_passed(),    the pairs the bound tests and where its
//     test_earliest()                       answers (Bound::test_pairs) go;
//   passed(bodies)                        from those, bodies.passed and bodies.earliest;
//   narrow_input(ctx, sample)             the narrow phase's motion and states;
//   narrow_pairs(bodies),                 the pairs it solves, with the `earliest` each
//     narrow_earliest(bodies)               starts from under narrow_from_earliest;
//   found(bodies, i, c)                   narrow pair i is in contact `c`;
//   contacts(bodies)                      after the last found: completes bodies.contacts.
#include <bounds/bound.hpp>
#include <ccd/narrow/narrow_query.hpp>
#include <pipeline/image_pairs.hpp>
#include <pipeline/pair_stage.hpp>
#include <pipeline/periodic_images.hpp>

#include <span>
#include <vector>

namespace ccd {

using BodyStage = PairStage<BodyPair, PairContact>;

/// The scene's bodies, each candidate pair tested and solved as itself.
class PlainBodies {
 public:
  static constexpr bool kScenery = true;

  /// `start_piece`: each body's piece at t0 (StateCursor::pieces), or empty.
  explicit PlainBodies(std::span<const std::size_t> start_piece) : start_piece_(start_piece) {}

  void prepare(Bound& bound, const StepContext& ctx, std::vector<Aabb>& boxes) const {
    if (!start_piece_.empty() && ctx.start_piece.empty() && ctx.exact == &ctx.motion->centres()) {
      // The bounds built from the pieces walk from the cursor's pieces instead of searching.
      StepContext with_pieces = ctx;
      with_pieces.start_piece = start_piece_;
      bound.prepare(with_pieces, boxes);
    } else {
      bound.prepare(ctx, boxes);
    }
  }
  static std::vector<BodyPair>& broad_pairs(BodyStage& bodies) { return bodies.candidates; }
  static void candidates(BodyStage&) {}
  static std::span<const BodyPair> test_pairs(const BodyStage& bodies) { return bodies.candidates; }
  static std::vector<BodyPair>& test_passed(BodyStage& bodies) { return bodies.passed; }
  static std::vector<double>& test_earliest(BodyStage& bodies) { return bodies.earliest; }
  static void passed(BodyStage&) {}
  NarrowInput narrow_input(const StepContext& ctx, bool sample) const {
    return {ctx.motion, ctx.start, start_piece_, ctx.t0, ctx.t1, sample};
  }
  static std::span<const BodyPair> narrow_pairs(const BodyStage& bodies) { return bodies.passed; }
  static std::span<const double> narrow_earliest(const BodyStage& bodies) { return bodies.earliest; }
  static void found(BodyStage& bodies, std::size_t i, const ContactResult& c) {
    bodies.contacts.push_back({bodies.passed[i], c});
  }
  static void contacts(BodyStage&) {}

 private:
  std::span<const std::size_t> start_piece_;
};

/// A scene that wraps around: the bodies and their images, each candidate body pair
/// tested and solved as its image pairs. The cursor's piece indices are not the unwrapped
/// paths': the local bodies' pieces are searched.
class ImageBodies {
 public:
  static constexpr bool kScenery = false;

  /// The bound prepared over the unwrapped bodies and, when some body has an image, again
  /// over the bodies and their images.
  void prepare(Bound& bound, const StepContext& ctx, std::vector<Aabb>& boxes) {
    bound.prepare(images_.begin(ctx), boxes);
    if (images_.add_images(boxes)) bound.prepare(images_.context(), boxes);
  }
  std::vector<BodyPair>& broad_pairs(BodyStage&) { return local_pairs_; }
  void candidates(BodyStage& bodies) {
    pairs_.group(local_pairs_, images_.owners(), images_.shifts(), bodies.candidates);
  }
  std::span<const BodyPair> test_pairs(const BodyStage&) const { return pairs_.tests(); }
  std::vector<BodyPair>& test_passed(BodyStage&) { return local_passed_; }
  std::vector<double>& test_earliest(BodyStage&) { return local_earliest_; }
  void passed(BodyStage& bodies) {
    pairs_.reduce_tests(local_passed_, local_earliest_, bodies.passed, bodies.earliest);
  }
  NarrowInput narrow_input(const StepContext& ctx, bool sample) const {
    return {&images_.motion(), images_.context().start, {}, ctx.t0, ctx.t1, sample};
  }
  std::span<const BodyPair> narrow_pairs(const BodyStage&) const { return pairs_.solve(); }
  std::span<const double> narrow_earliest(const BodyStage&) const { return pairs_.solve_earliest(); }
  void found(BodyStage&, std::size_t i, const ContactResult& c) { pairs_.keep(i, c); }
  void contacts(BodyStage& bodies) const {
    pairs_.for_each_contact([&](const BodyPair& p, const ContactResult& c) {
      bodies.contacts.push_back({p, c});
    });
  }

  const PeriodicImages& images() const { return images_; }

 private:
  PeriodicImages images_;
  ImagePairs pairs_;
  std::vector<BodyPair> local_pairs_;
  std::vector<BodyPair> local_passed_;
  std::vector<double> local_earliest_;
};

}  // namespace ccd
