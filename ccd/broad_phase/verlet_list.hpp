#pragma once
// A Verlet list for a rebuilding broad phase (`grid`, `hgrid`): the pairs found once on
// boxes grown by a margin ("fat" boxes) serve the following frames for as long as every
// box stays inside its fat box.
//
// Exact. While box_i lies in fat_i for every i (closed intervals), two overlapping boxes
// have overlapping fat boxes, so every overlapping pair is on the list; a frame served from
// the list gives each listed pair the exact box test and reports the pairs that pass: the
// same set as a rebuild (and as `brute`), in the list's order. fl(lo - m) <= lo and
// fl(hi + m) >= hi for m >= 0, so rounding never shrinks a fat box below its box.
//
// Margins. At a rebuild each body's margin is `reuse` times its mean motion per frame
// since the previous rebuild (the largest change of any face of its box, over the frames
// in between), capped at a quarter of its box's largest extent: a body moving steadily
// stays inside for about `reuse` frames. On the first build (and after a change of body
// count) the margin is 1/64 of the extent. A body at rest gets margin 0 and stays inside
// until it moves.
// Backing off. When the first frame after a rebuild already finds a box outside, or when
// some body's margin would not last two frames of its motion (the cap binds: the motion
// per frame is a large part of its box), margins do not pay: that rebuild and the next use
// plain boxes and skip the containment check, for 1, 2, 4, ... 64 frames, doubling while
// this repeats, back to 1 when a list serves a frame.
// Cost per served frame: one containment test per body and one box test per listed pair.
#include <ccd/broad_phase/broad_phase.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd::detail {

class VerletList {
 public:
  /// The default `reuse` of `grid` and `hgrid`.
  static constexpr unsigned kDefaultReuse = 32;
  /// `reuse` frames a list is meant to serve (0: off, every frame rebuilds).
  explicit VerletList(unsigned reuse) : reuse_(reuse) {}

  /// One frame of a rebuilding broad phase: served from the list, or `rebuild(boxes, pairs)`
  /// (the method's own pass, which sets `stats` with rebuilt = true) run on the grown boxes
  /// and adopted. Writes the overlapping pairs into `out` (cleared first).
  template <class Rebuild>
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out, BroadPhaseStats& stats,
                  Rebuild&& rebuild) {
    std::uint64_t tests = 0;
    if (serve(boxes, out, tests)) {
      stats = {};
      stats.box_tests = tests;
      return;
    }
    rebuild(fat_boxes(boxes), found_);
    stats.box_tests += adopt(boxes, found_, out);
  }

 private:
  /// Serves the frame from the list when every box is inside its fat box: writes the
  /// overlapping listed pairs into `out` (cleared first), sets `box_tests`, returns true.
  /// False: find_pairs rebuilds (fat_boxes(), then adopt()).
  bool serve(std::span<const Aabb> boxes, std::vector<BodyPair>& out, std::uint64_t& box_tests);
  /// The boxes a rebuild runs on: `boxes` grown by their margins, or `boxes` itself when
  /// the list is off or backing off.
  std::span<const Aabb> fat_boxes(std::span<const Aabb> boxes);
  /// Takes the pairs the rebuild found on fat_boxes() (`found`, consumed) as the new list
  /// and writes those whose `boxes` overlap into `out` (cleared first); returns the box
  /// tests spent. When fat_boxes() returned `boxes` itself, `found` is already the answer:
  /// it is swapped into `out` and nothing is kept.
  std::uint64_t adopt(std::span<const Aabb> boxes, std::vector<BodyPair>& found, std::vector<BodyPair>& out);
  void back_off();  // plain rebuilds for the next backoff period, doubling it

  unsigned reuse_;
  bool listed_ = false;   // list_ and fat_ describe the current body set
  bool fattened_ = false;  // the last fat_boxes() grew the boxes
  std::uint32_t served_ = 0;    // frames served since the last rebuild
  std::uint32_t backoff_ = 0;   // plain rebuilds left before the next fat one
  std::uint32_t next_backoff_ = 1;
  std::vector<Aabb> fat_;     // per body, its fat box
  std::vector<Aabb> anchor_;  // per body, its box at the last rebuild
  std::uint32_t anchor_frames_ = 0;  // frames from the anchor to now (0: no anchor)
  std::vector<BodyPair> list_;
  std::vector<BodyPair> found_;  // a rebuild's pairs on the grown boxes
};

}  // namespace ccd::detail
