#pragma once
// Every body's state at a sequence of non-decreasing times, with one cursor per body into
// its trajectory pieces (ccd/motion/trajectory.hpp): no binary search per step. At a
// piece break the later piece is used, as Trajectories::piece_at does. A time earlier
// than the previous one is the caller's error (the cursors do not move back).
#include <ccd/motion/body_state.hpp>
#include <ccd/motion/trajectory.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace ccd {

class StateCursor {
 public:
  explicit StateCursor(const Trajectories& motion) : motion_(motion), cursor_(motion.size(), 0) {}
  /// Writes the state of every body at time t into `out` (resized to the body count).
  void evaluate(double t, std::vector<BodyState>& out);
  /// Index into pieces(body) of the piece each body was evaluated on at the last time.
  std::span<const std::size_t> pieces() const { return cursor_; }

 private:
  const Trajectories& motion_;
  std::vector<std::size_t> cursor_;
};

}  // namespace ccd
