#pragma once
// The bound interface. A bound encloses what a body may occupy, either at one instant
// (`sphere`, `aabb`: discrete methods, checked at sample times) or over a whole step
// [t0, t1] (space-time bounds: conservative continuous methods). Each bound gives one AABB
// per body, so every broad phase of ccd/broad_phase/registry.hpp can cull with it, and a
// pair test of its own that filters the broad phase's pairs. The registry is
// bounds/registry.hpp; method names compose as BOUND/BROADPHASE.
#include <bounds/volume.hpp>
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/motion/body_state.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene.hpp>
#include <ccd/scene/scenery.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace ccd {

/// What a bound may know about a body at the start of a step.
enum class Knowledge {
  Instant,  ///< position at the sample time only (discrete methods)
  Exact,    ///< the true piecewise-quadratic motion over the step
  Bounded,  ///< position and velocity at t0 and a bound A on |acceleration| (Hubbard)
};

/// "instant", "exact", "bounded" (results files, `ccdlab methods`).
constexpr std::string_view to_string(Knowledge k) {
  switch (k) {
    case Knowledge::Instant: return "instant";
    case Knowledge::Exact: return "exact";
    case Knowledge::Bounded: return "bounded";
  }
  return "unknown";
}

/// What a bound's pair test found (Box2D's b2TOIOutput style: a status and the time).
struct PairTest {
  enum class Status : std::uint8_t {
    Disjoint,  ///< the two bounds do not meet during the step: no contact possible
    Possible,  ///< the bounds meet: contact possible from `earliest` on
  };
  Status status = Status::Disjoint;
  /// Possible: the earliest time in [t0, t1] at which contact is possible under the
  /// bound (t0 when the bound carries no timing). Disjoint: +infinity.
  double earliest = std::numeric_limits<double>::infinity();
  bool possible() const { return status == Status::Possible; }
  static PairTest disjoint() { return {}; }
  static PairTest possible_from(double t) { return {Status::Possible, t}; }
};

/// The time window a body's bound covers (seconds). After `prepare` every body has the
/// step's window; a scheduler's `refresh` gives some bodies a later one.
struct Window {
  double t0 = 0.0;
  double t1 = 0.0;
};

/// The part of time both windows cover, [max t0, min t1]; empty when lo > hi.
inline Window common_window(const Window& a, const Window& b) {
  return {a.t0 > b.t0 ? a.t0 : b.t0, a.t1 < b.t1 ? a.t1 : b.t1};
}

struct StepContext {
  double t0 = 0.0;                       ///< step start (the sample time for Instant bounds)
  double t1 = 0.0;                       ///< step end (== t0 for Instant bounds)
  std::span<const BodyState> start;      ///< every body's state at t0 (always given)
  /// The true motion, given only to Exact bounds: &motion->centres() for them, else null.
  const Trajectories* exact = nullptr;
  double acceleration_bound = 0.0;       ///< A for Bounded bounds
  std::optional<WallBox> walls;          ///< the scene's static walls (known to every bound)
  /// Required: the scene's motion (ccd/motion/rigid_motion.hpp), the same object the
  /// narrow phase reads. Every bound may ask it for the bodies' shapes and spin (the
  /// orientation-aware bounds frame_aabb, obb, obb_sat do; every other bound sees each
  /// body as its enclosing sphere, BodyState::radius). Its centres' trajectories are the
  /// exact motion: only an Exact bound reads them, through `exact`.
  const RigidMotion* motion = nullptr;
  /// Optional, with `exact`: each body's piece index at t0 in `exact` (StateCursor::pieces:
  /// the later piece at a break, as Trajectories::piece_index), so that the bounds built
  /// from the pieces walk from it instead of searching. Empty: they search.
  std::span<const std::size_t> start_piece{};

  /// The index of `body`'s piece at t0 in `exact`: start_piece[body] when given, else
  /// Trajectories::piece_index (the same index).
  std::size_t piece_at_t0(std::size_t body) const {
    return start_piece.empty() ? exact->piece_index(body, t0) : start_piece[body];
  }
};

class Bound {
 public:
  virtual ~Bound() = default;
  /// Computes the per-body data for the step and writes one AABB per body into `boxes`
  /// (resized to the body count): the box the body may occupy during the step.
  virtual void prepare(const StepContext& ctx, std::vector<Aabb>& boxes) = 0;
  /// The bound's own test for a pair the broad phase reported: Disjoint only when the
  /// two bounds are disjoint, else Possible with the earliest possible contact time.
  /// The bodies' windows may differ (after `refresh`): the test then covers the common
  /// part of both windows (common_window) and is Disjoint when that part is empty;
  /// `earliest` lies in it, and no contact is possible in it before `earliest` while the
  /// bound's assumption holds (every conservative bound guarantees this; bounds without
  /// timing return the common window's start).
  virtual PairTest test(std::uint32_t a, std::uint32_t b) const = 0;
  /// `test` for every pair of `pairs`, in order: each Possible pair is appended to `passed`
  /// and its `earliest` to `earliest` (the step pipeline's stage 3). The default calls
  /// `test` pair by pair; a bound may override it to fetch the data of the pairs ahead
  /// (the pairs of a broad phase name scattered bodies), with the same answers.
  virtual void test_pairs(std::span<const BodyPair> pairs, std::vector<BodyPair>& passed,
                          std::vector<double>& earliest) const;
  /// For a scheduler (pipeline/earliest_scheduler.hpp): rebuilds the data of `bodies`
  /// only, over the window [ctx.t0, ctx.t1], from ctx.start (indexed by body; only the
  /// listed entries are read) and writes their boxes into boxes[body]; every other body
  /// keeps its window and data. Without a `prepare` first, only the refreshed bodies
  /// hold a bound (a scheduler's scratch instance for single pairs). Instant bounds have
  /// no window: the default throws std::logic_error.
  virtual void refresh(const StepContext& ctx, std::span<const std::uint32_t> bodies, std::span<Aabb> boxes);
  /// The window body `body` covers since its last prepare or refresh.
  virtual Window window(std::uint32_t body) const = 0;
  /// Appends to `out` the volumes this bound tests for `body` since its last prepare or
  /// refresh (bounds/volume.hpp), built from the data its pair test reads: together they
  /// hold the body over its window, each over its own time span (a sub-interval's volume
  /// holds the body over that sub-interval). What the viewer draws (docs/viewer.md) and
  /// what tests/bounds/volumes_test.cpp checks against the motion and against the boxes.
  virtual void volumes(std::uint32_t body, std::vector<Volume>& out) const = 0;
  /// The bound's test of body `body` against a static polygon of the scenery (the static
  /// index's pair, ccd/broad_phase/static_index.hpp): Disjoint only when the body's bound
  /// cannot meet the polygon in the body's window, else Possible with the earliest time
  /// of possible contact in the window. `body_box` is the box this bound wrote for the body
  /// (prepare or refresh), `polygon_box` the polygon's (polygon_box). The bound keeps no
  /// scenery of its own: the caller owns the polygons. Default: box overlap,
  /// `earliest` = the window's start. Bounds with a tighter shape override it (sphere,
  /// swept_aabb, capsule, horn, enclosing_sphere; docs/scenery-methods.md). Every
  /// override is conservative as the pair test is: if the body (its true path within the
  /// window, under the bound's assumption) touches the polygon, the answer is Possible
  /// with `earliest` no later than the first touch.
  virtual PairTest test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon& polygon,
                               const Aabb& polygon_box) const;
};

}  // namespace ccd
