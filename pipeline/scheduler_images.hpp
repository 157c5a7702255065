#pragma once
// The earliest-contact scheduler's image layer for scenes that wrap around
// (ccd/scene/periodic.hpp; the scheduler is pipeline/earliest_scheduler.hpp). The step
// pipeline's layer (pipeline/periodic_images.hpp) rebuilds every body and image per
// step; the scheduler refreshes bodies one by one, so here images are *slots*: ids of the
// bound and of the broad phase that live as long as their body's window.
//
// Paths. Each body's exact pieces are unwrapped once over the whole horizon: piece j is
// moved by turns_j periods (the periods the body jumped at its wraps before piece j), so
// the unwrapped path G is continuous on wrapped axes. A slot holds body `owner`'s path
// G + shift x L (shift: whole periods per axis, the slot's absolute image shift), as exact
// pieces (each original piece moved once by its exact double-double offset).
//  - Home slots: slot i (i < n) is body i over its current window [w0, w1]; set_home gives
//    it the shift that puts the piece containing w0 (the later one at a break) where it is,
//    so the home's state at w0 is the body's own.
//  - Image slots (>= n): after the home's bound is built, every image of its box that meets
//    the cell [min, max] on the wrapped axes (PeriodicBox::for_each_image) gets a slot with
//    shift = home shift + image shift, from a pool of slots reused as windows expire. A free
//    slot's box is a point parked outside every active box (distinct points along a
//    diagonal, so they never overlap anything), so broad phases need no removal.
// Why the broad phase finds every periodic pair: if a and b can touch through a lattice
// shift, a's box and b's box moved by that shift overlap; the overlap moved into the cell
// lies in one image (slot) of each, and those two slots' boxes overlap. Two slot pairs of
// the same bodies with the same relative shift (shift(y) - shift(x)) are the same image
// pair (their bounds are translates): the scheduler keeps one.
// Views: a bound or narrow phase reads a Trajectories indexed like its ids, so view() gives
// one with size() bodies in which only the listed slots have pieces (those overlapping the
// window), and pair_view() one with two bodies (the pair's slots) for the narrow phase and a
// pair's own bounds. Unwrapped views have no periodic box: bounds and narrow phases see free
// motion on wrapped axes (walls there are opened by the scheduler).
#include <ccd/geometry/aabb.hpp>
#include <ccd/motion/body_state.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/periodic.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

class SchedulerImages {
 public:
  static constexpr std::uint32_t kFree = 0xffffffffu;  ///< owner of a slot in the pool

  /// n home slots (slot i = body i) for `motion`, which must be periodic; no images yet.
  void begin(const Trajectories& motion);

  std::size_t size() const { return owner_.size(); }
  /// The body a slot belongs to, kFree for a pooled slot.
  std::uint32_t owner(std::uint32_t slot) const { return owner_[slot]; }
  /// The slot's absolute image shift (periods per axis) relative to its owner's unwrapped path.
  const ImageShift& shift(std::uint32_t slot) const { return shift_[slot]; }
  /// Relative shift of y's image against x's: shift(y) - shift(x).
  ImageShift relative(std::uint32_t x, std::uint32_t y) const;

  /// Body `body`'s home slot for a window starting at t (see above).
  void set_home(std::uint32_t body, double t);
  /// The state of slot's path at time t (the later piece at a break).
  BodyState state(std::uint32_t slot, double t) const;

  /// Gives body `body` one image slot per image of `home_box` (its home slot's box) that
  /// meets the cell, other than the home itself: its previous image slots are reused first,
  /// then pooled ones (the pool, `boxes` and the slot count grow when empty). Appends the
  /// body's image slots to `images` and the slots it gave back to the pool (their boxes now
  /// parked) to `freed`. Throws std::length_error for a box over more than kMaxImageSpan periods.
  void set_images(std::uint32_t body, const Aabb& home_box, std::vector<Aabb>& boxes,
                  std::vector<std::uint32_t>& images, std::vector<std::uint32_t>& freed);
  /// Call with every new active box: when it reaches the parking area, the pool's points move
  /// further out and every pooled slot is appended to `moved`.
  void keep_clear(const Aabb& active, std::vector<Aabb>& boxes, std::vector<std::uint32_t>& moved);

  /// size() bodies; the listed slots (distinct) with their pieces over [u0, u1], the others empty.
  const Trajectories& view(std::span<const std::uint32_t> slots, double u0, double u1);
  /// Two bodies: slot x's path (body 0) and slot y's (body 1) over [u0, u1].
  const Trajectories& pair_view(std::uint32_t x, std::uint32_t y, double u0, double u1);

 private:
  void append_path(Trajectories& out, std::uint32_t slot, double u0, double u1);
  std::uint32_t take_slot(std::vector<Aabb>& boxes);
  Aabb parked(std::uint32_t slot) const;

  const Trajectories* motion_ = nullptr;
  PeriodicBox box_;
  std::vector<std::uint32_t> first_turn_;  ///< per body: index of its first piece in turns_ (n + 1)
  std::vector<ImageShift> turns_;          ///< per original piece: periods it is moved by in G
  std::vector<std::uint32_t> owner_;
  std::vector<ImageShift> shift_;
  std::vector<std::vector<std::uint32_t>> images_;  ///< per body: its image slots
  std::vector<std::uint32_t> pool_;                 ///< free slots
  Vec3 park_{Vec3::Zero()};                         ///< pooled slot s sits at park_ - s step_ (1, 1, 1)
  double step_ = 0.0;
  std::vector<char> listed_;
  std::vector<DdVec3> offsets_;
  Trajectories view_, pair_view_;
};

}  // namespace ccd
