#pragma once
// The bound interface. A bound encloses what a body may occupy, either at one instant
// (`sphere`, `aabb`: discrete methods, checked at sample times) or over a whole step
// [t0, t1] (space-time bounds: conservative continuous methods). Each bound gives one AABB
// per body, so every broad phase of ccd/broad_phase/registry.hpp can cull with it, and a
// pair test of its own that filters the broad phase's pairs. The registry is
// bounds/registry.hpp; method names compose as BOUND/BROADPHASE.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene.hpp>

#include <optional>
#include <span>
#include <vector>

namespace ccd {

/// What a bound may know about a body at the start of a step.
enum class Knowledge {
  Instant,  ///< position at the sample time only (discrete methods)
  Exact,    ///< the true piecewise-quadratic motion over the step
  Bounded,  ///< position and velocity at t0 and a bound A on |acceleration| (Hubbard)
};

/// State of a body at the start of a step: all a `Bounded` bound may read.
struct BodyState {
  Vec3 position{Vec3::Zero()};
  Vec3 velocity{Vec3::Zero()};
  double radius = 0.0;
};

struct StepContext {
  double t0 = 0.0;                       ///< step start (the sample time for Instant bounds)
  double t1 = 0.0;                       ///< step end (== t0 for Instant bounds)
  std::span<const BodyState> start;      ///< every body's state at t0 (always given)
  const Trajectories* exact = nullptr;   ///< the true motion: given only to Exact bounds
  double acceleration_bound = 0.0;       ///< A for Bounded bounds
  std::optional<WallBox> walls;          ///< the scene's static walls (known to every bound)
};

class Bound {
 public:
  virtual ~Bound() = default;
  /// Computes the per-body data for the step and writes one AABB per body into `boxes`
  /// (resized to the body count): the box the body may occupy during the step.
  virtual void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) = 0;
  /// The bound's own test for a pair the broad phase reported: false only when the two
  /// bounds are disjoint. On true, `*earliest` (if not null) receives the earliest time
  /// in [t0, t1] at which contact is possible under this bound (t0 when unknown).
  virtual bool test(std::uint32_t a, std::uint32_t b, double* earliest) const = 0;
};

}  // namespace ccd
