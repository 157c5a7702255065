#pragma once
// The input every narrow-phase entry reads (ccd/narrow/narrow_table.hpp): the scene's
// motion (centres, shapes, spin), the bodies' states at the step start, and the step.
#include <ccd/motion/body_state.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>

#include <cstddef>
#include <span>

namespace ccd {

struct NarrowInput {
  /// Required: the scene's motion (ccd/motion/rigid_motion.hpp): the centres' exact
  /// trajectories (step queries), and the shapes, orientations and point-speed bounds that
  /// every entry but sphere x sphere reads.
  const RigidMotion* motion = nullptr;
  std::span<const BodyState> start;      ///< every body's state at t0 (sample tests)
  /// Optional: the index into motion->centres().pieces(i) of the piece body i is on at t0
  /// (StateCursor::pieces), so a sample test need not search for it. Empty: searched.
  std::span<const std::size_t> start_piece;
  double t0 = 0.0;                       ///< step start, seconds
  double t1 = 0.0;                       ///< step end (== t0 for a sample test)
  /// true: a sample test, "in contact at t0?" (discrete methods); false:
  /// the first contact in [t0, t1] from `motion` (continuous methods).
  bool sample = false;
};

}  // namespace ccd
