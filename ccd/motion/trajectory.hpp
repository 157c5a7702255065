#pragma once
// Exact piecewise-quadratic trajectories of a scene's bodies over [0, horizon].
//
// A piece covers [t0, t1] with p(t) = p + v s + a s^2 / 2, s = t - t0. Pieces end at
// elastic wall reflections (solved exactly: the first s > 0 at which the centre reaches
// min + r or max - r on some axis while moving towards that wall; the velocity
// component flips and the position is set exactly on the wall) and at the body's
// acceleration changes. A body touching a wall with zero normal velocity while its
// acceleration pushes it into the wall rests on that wall: the wall supplies the
// normal force, so that acceleration component is zero on the piece (the limit of
// ever smaller elastic bounces).
//
// Guarantee: consecutive pieces of a body are continuous in position (the next piece
// starts at the previous piece's end point as evaluated, or exactly on the wall).
// Limits: at most `max_pieces_per_body` pieces per body (a body that would need more
// throws TooManyPieces naming it: a ball bouncing ever faster).
#include <ccd/geometry/aabb.hpp>
#include <ccd/scene/scene.hpp>

#include <cstdint>
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
  std::size_t total_pieces() const { return pieces_.size(); }
  /// The piece of `body` that contains time t (the later one at a break).
  const Piece& piece_at(std::size_t body, double t) const;
  Vec3 position(std::size_t body, double t) const { return piece_at(body, t).position(t); }
  Vec3 velocity(std::size_t body, double t) const { return piece_at(body, t).velocity(t); }
  /// Box of the whole sphere of `body` over [u0, u1] (exact for the path, plus radius).
  Aabb swept_bounds(std::size_t body, double u0, double u1) const;

 private:
  double horizon_ = 0.0;
  std::vector<double> radius_;
  std::vector<Piece> pieces_;
  std::vector<std::uint32_t> first_{0};
};

}  // namespace ccd
