#pragma once
// Exact piecewise-quadratic trajectories of a scene's bodies over [0, horizon].
//
// A piece covers [t0, t1] with p(t) = p + v s + a s^2 / 2, s = t - t0. Pieces end at
// elastic wall reflections and at the body's acceleration changes.
//
// The model (docs/truth.md, "Motion model"):
//  - A wall plane is the exact real number min + r (or max - r), not its rounding.
//  - A reflection happens at the first s > 0 at which the centre reaches a wall plane
//    while moving towards it; the normal velocity component flips (restitution 1).
//  - A body that starts on or beyond a wall plane while moving into it reflects at once.
//  - Resting rule: when a body's acceleration pushes it into a wall and the highest point
//    it can reach above that wall plane, h + v_n^2 / (2 |a_n|), is at most
//    rest_height = 2^-30 x (box extent on that axis), the body rests on the wall: on the
//    piece its normal position is the plane, its normal velocity and acceleration zero
//    (the wall supplies the normal force). This replaces ever faster micro-bounces (a
//    soft landing, a body 1e-10 above the floor) by the state they converge to.
//
// Precision: every piece's start state (position, velocity, acceleration) is kept in
// double-double (the Piece fields hold the leading doubles, PieceLow the trailing ones),
// so breaks at acceleration changes and exactly representable reflections carry no
// rounding of their own (about 1e-32 relative). Piece times are doubles: when a
// reflection time is not a double, the piece boundary t_r is the nearest double, each
// piece follows its exact branch (extrapolated by |t* - t_r|), and PieceLow records the
// window |t* - t_r| and the position error 2 |v_n| |t* - t_r| inside it, and the
// rounding of the double-double operations carried from break to break (about
// 32 u^2 of the magnitudes per break, u = 2^-53).
// Wrapped axes (ccd/scene/periodic.hpp): a piece also ends when the centre reaches a face
// (min or max itself, not min + r) while moving out through it; the next piece starts at
// the opposite face with the same velocity and acceleration (position moved by one exact
// period, so no model error). A centre that starts on or beyond a face moving (or, at
// rest, accelerating) out through it re-enters at once. Positions therefore stay in
// [min, max] on wrapped axes, up to the rounding of the piece's end time.
// Limits: at most `max_pieces_per_body` pieces per body (a body that would need more
// throws TooManyPieces naming it: a ball bouncing ever faster).
#include <ccd/geometry/aabb.hpp>
#include <ccd/geometry/double_double.hpp>
#include <ccd/scene/periodic.hpp>
#include <ccd/scene/scene.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace ccd {

struct Piece {
  double t0 = 0.0;
  double t1 = 0.0;
  Vec3 p{Vec3::Zero()};
  Vec3 v{Vec3::Zero()};
  Vec3 a{Vec3::Zero()};

  Vec3 position(double t) const {
    const double s = t - t0;
    return p + v * s + a * (0.5 * s * s);
  }
  Vec3 velocity(double t) const { return v + a * (t - t0); }
  /// Tight box of the centre's path over [u0, u1] ⊆ [t0, t1] (endpoints and the vertex).
  Aabb centre_bounds(double u0, double u1) const;
};

/// A body needs more than TrajectoryOptions::max_pieces_per_body pieces.
class TooManyPieces : public std::runtime_error {
 public:
  TooManyPieces(std::size_t body, std::size_t limit)
      : std::runtime_error("body " + std::to_string(body) + " needs more than " + std::to_string(limit) +
                           " trajectory pieces (wall reflections) over the horizon"),
        body_(body), limit_(limit) {}
  std::size_t body() const { return body_; }
  std::size_t limit() const { return limit_; }

 private:
  std::size_t body_;
  std::size_t limit_;
};

/// The trailing parts of a piece's start state and the model's error at its ends.
struct PieceLow {
  Vec3 p{Vec3::Zero()};  ///< exact start position = Piece::p + p
  Vec3 v{Vec3::Zero()};  ///< exact start velocity = Piece::v + v
  Vec3 a{Vec3::Zero()};  ///< exact acceleration = Piece::a + a (own + gravity is not always a double)
  double edge_window = 0.0;  ///< seconds: within this of either end the model may be off by
  double edge_error = 0.0;   ///< metres: at most this (an inexact reflection time); 0 otherwise
  /// Bounds on the double-double rounding carried into this piece's start state by the
  /// breaks before it (0 on a body's first piece, whose state is the scene's data):
  /// position error <= start_error + velocity_error |t - t0| on the piece.
  double start_error = 0.0;     ///< metres
  double velocity_error = 0.0;  ///< metres per second
};

/// Exact (double-double) position and velocity of piece q at time t (any double t; the
/// offset t - q.t0 is formed exactly).
DdVec3 exact_position(const Piece& q, const PieceLow& low, double t);
DdVec3 exact_velocity(const Piece& q, const PieceLow& low, double t);

/// Moves piece q (with its trailing parts) by `shift`, exactly in double-double: a
/// periodic image of the piece.
void shift_piece(Piece& q, PieceLow& low, const DdVec3& shift);
/// The exact shift of image `s` as double-doubles.
DdVec3 image_offset(const PeriodicBox& box, const ImageShift& s);

struct TrajectoryOptions {
  static constexpr std::size_t default_max_pieces_per_body = 1000000;
  std::size_t max_pieces_per_body = default_max_pieces_per_body;
};

class Trajectories {
 public:
  Trajectories() = default;
  /// Builds every body's trajectory over [0, scene.horizon].
  explicit Trajectories(const Scene& scene, const TrajectoryOptions& options = {});

  std::size_t size() const { return radius_.size(); }
  double horizon() const { return horizon_; }
  double radius(std::size_t body) const { return radius_[body]; }
  std::span<const Piece> pieces(std::size_t body) const {
    return {pieces_.data() + first_[body], pieces_.data() + first_[body + 1]};
  }
  /// Trailing parts of the pieces of `body`, index for index.
  std::span<const PieceLow> lows(std::size_t body) const {
    return {lows_.data() + first_[body], lows_.data() + first_[body + 1]};
  }
  std::size_t total_pieces() const { return pieces_.size(); }
  /// Index (into pieces(body)) of the piece that contains time t (the later one at a break).
  std::size_t piece_index(std::size_t body, double t) const;
  /// The piece of `body` that contains time t (the later one at a break).
  const Piece& piece_at(std::size_t body, double t) const;
  Vec3 position(std::size_t body, double t) const { return piece_at(body, t).position(t); }
  Vec3 velocity(std::size_t body, double t) const { return piece_at(body, t).velocity(t); }
  /// The box's periodic axes; null when no axis wraps.
  const PeriodicBox* periodic() const { return periodic_ ? &*periodic_ : nullptr; }
  /// Empties the set (for append_body), keeping its buffers.
  void reset(double horizon, const std::optional<PeriodicBox>& periodic);
  /// Appends a body made of `pieces` (with their `lows`), piece j moved by shifts[j]
  /// (exact double-double addition): the step pipeline's periodic images.
  void append_body(double radius, std::span<const Piece> pieces, std::span<const PieceLow> lows,
                   std::span<const DdVec3> shifts);
  /// Box of the whole sphere of `body` over [u0, u1] (exact for the path, plus radius).
  Aabb swept_bounds(std::size_t body, double u0, double u1) const;

 private:
  double horizon_ = 0.0;
  std::optional<PeriodicBox> periodic_;
  std::vector<double> radius_;
  std::vector<Piece> pieces_;
  std::vector<PieceLow> lows_;
  std::vector<std::uint32_t> first_{0};
};

}  // namespace ccd
