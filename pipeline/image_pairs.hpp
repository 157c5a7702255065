#pragma once
// The image pairs of one step of a scene that wraps around, grouped by body pair: how the
// step pipeline (pipeline/step_pipeline.hpp) maps the broad phase's pairs of local bodies
// (pipeline/periodic_images.hpp: the bodies and their images) to the pairs of bodies it
// reports, and reduces the answers of the bound's test and of the narrow phase per body
// pair.
//
//  - group: each local pair (x, y) becomes the image pair (a, b, shift) of its owners
//    a < b, `shift` the image shift of b's local body relative to a's; pairs of a body with
//    its own image are dropped and each (a, b, shift) is kept once (sorted by a, b, shift).
//    Every body pair with at least one image pair is a candidate, once, in that order.
//  - test: the bound tests each image pair as the local pair (min(x, y), max(x, y)); a body
//    pair passes when any of its image pairs passes, with `earliest` the least of theirs.
//  - solve: the narrow phase solves each passing image pair as (x, y) (a's local body
//    first) from that image pair's own `earliest`; a body pair's contact is the earliest
//    (least toi; the first in order on a tie) over its image pairs.
// Two image pairs of one body pair never share a local pair (the local pair gives the
// owners and the shift), so the passed local pairs name their image pairs.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/narrow/contact_result.hpp>
#include <ccd/scene/periodic.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

class ImagePairs {
 public:
  /// Groups the broad phase's `local` pairs; owner[x] and shift[x] describe local body x.
  /// Overwrites `bodies` with the body pairs (a < b, each once, sorted).
  void group(std::span<const BodyPair> local, std::span<const std::uint32_t> owner,
             std::span<const ImageShift> shift, std::vector<BodyPair>& bodies);

  /// The local pairs the bound tests, one per image pair, in order (x < y).
  std::span<const BodyPair> tests() const { return tests_; }
  /// From the bound's answers on tests() (`passed`: those that passed, in order, with
  /// their `earliest`): appends the passing body pairs and their least `earliest` to
  /// `body_passed` and `body_earliest`, and lists the image pairs to solve.
  void reduce_tests(std::span<const BodyPair> passed, std::span<const double> earliest,
                    std::vector<BodyPair>& body_passed, std::vector<double>& body_earliest);

  /// The passing image pairs as the narrow phase solves them: (a's local body, b's).
  std::span<const BodyPair> solve() const { return solve_; }
  /// Per pair of solve(), its own test's `earliest`.
  std::span<const double> solve_earliest() const { return solve_earliest_; }
  /// The narrow phase found `c` for solve()[i]: kept when it is its body pair's earliest so far.
  void keep(std::size_t i, const ContactResult& c);
  /// f(body pair, contact) for each body pair with a contact kept, in the order of the
  /// passing body pairs.
  template <class F>
  void for_each_contact(F&& f) const {
    for (std::size_t k = 0; k < best_.size(); ++k)
      if (has_best_[k]) f(passed_bodies_[k], best_[k]);
  }

 private:
  struct ImagePair {
    std::uint32_t a, b;  // bodies, a < b
    ImageShift shift;    // of b's local body relative to a's
    std::uint32_t x, y;  // local bodies (owners a and b)
  };
  std::vector<ImagePair> pairs_;
  std::vector<BodyPair> tests_;
  std::vector<BodyPair> solve_;
  std::vector<double> solve_earliest_;
  std::vector<std::uint32_t> solve_group_;  // per solve pair: index into passed_bodies_
  std::vector<BodyPair> passed_bodies_;
  std::vector<ContactResult> best_;
  std::vector<char> has_best_;
};

}  // namespace ccd
