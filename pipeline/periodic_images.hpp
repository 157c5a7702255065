#pragma once
// The generic image layer of the step pipeline for scenes that wrap around
// (ccd/scene/periodic.hpp): it lets every bound and every broad phase work on a periodic
// scene unchanged.
//
// For a step [t0, t1] it builds a local set of bodies (`motion()`, whose centres are the
// local paths):
//  1. each body, its pieces that overlap the step unwrapped: a piece after a wrap is moved
//     back by the period, so the body's path over the step is continuous (the bounds see
//     free motion on wrapped axes: their walls there are at -inf and +inf);
//  2. after `add_images(boxes)`, every periodic image of each body whose box (the bound's
//     box of the unwrapped body) meets the cell [min, max] on the wrapped axes, as a body
//     of its own, appended after the n bodies (PeriodicBox::for_each_image).
// Two bodies that can touch through some image shift have boxes that overlap after that
// shift, so the broad phase over the local set reports them (as some pair of their
// images) and the bound's pair test and the narrow phase of that pair decide, with the
// shift built in. `owner` and `shift` map a local body back; pairs of two images of one
// body are dropped (the box edge is at least twice the diameter: a body never touches its
// own image). Conservative: the images' paths are the bodies' exact paths moved by exact
// periods (double-double), so every bound's guarantee carries over. A wrap leaves the
// orientation alone, so every local body keeps its owner's shape and spin (`motion()`):
// the orientation-aware bounds and the narrow phase see an image as the body itself,
// moved by whole periods.
#include <bounds/bound.hpp>
#include <ccd/motion/body_state.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/periodic.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

/// x + y and x - y, axis by axis.
inline ImageShift shift_sum(const ImageShift& x, const ImageShift& y) {
  return {x[0] + y[0], x[1] + y[1], x[2] + y[2]};
}
inline ImageShift shift_difference(const ImageShift& x, const ImageShift& y) {
  return {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
}

/// Periods a body jumped by (per wrapped axis) from piece `prev` to the next piece `next`:
/// the end of prev and the start of next differ by a whole number of periods (0 at breaks
/// other than a wrap).
ImageShift wrap_jump(const PeriodicBox& box, const Piece& prev, const Piece& next);

class PeriodicImages {
 public:
  /// Builds the n unwrapped bodies of the step ctx.t0..ctx.t1 of ctx.motion (periodic).
  /// The returned context is ctx with the local states, the local motion (`motion()`:
  /// every local body with its owner's shape and spin; its centres as ctx.exact when
  /// ctx.exact was given) and walls opened on the wrapped axes.
  const StepContext& begin(const StepContext& ctx);
  /// Appends the images of every body whose box (boxes[0..n)) meets the cell; returns
  /// whether there are any (then the bound must be prepared again over context()).
  bool add_images(const std::vector<Aabb>& boxes);

  const StepContext& context() const { return ctx_; }
  /// The local bodies' motion: their owners' shapes and spins, centres on the local paths.
  const RigidMotion& motion() const { return motion_; }
  std::uint32_t owner(std::uint32_t local) const { return owner_[local]; }
  const ImageShift& shift(std::uint32_t local) const { return shift_[local]; }
  /// owner() and shift() of every local body, indexed by local body.
  std::span<const std::uint32_t> owners() const { return owner_; }
  std::span<const ImageShift> shifts() const { return shift_; }

 private:
  const RigidMotion* source_ = nullptr;
  StepContext ctx_;
  Trajectories local_;
  std::vector<BodyState> states_;
  std::vector<std::uint32_t> owner_;
  std::vector<ImageShift> shift_;
  std::vector<DdVec3> piece_shift_;   ///< per local piece of the n bodies: the unwrapping
  std::vector<std::uint32_t> first_;  ///< per body: first index into piece_shift_ (n + 1)
  std::vector<std::size_t> first_piece_;  ///< per body: index of its first local piece in source pieces
  std::vector<DdVec3> scratch_;
  RigidMotion motion_;  ///< over local_
};

}  // namespace ccd
