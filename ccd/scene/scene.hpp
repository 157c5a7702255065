#pragma once
// A scene: spheres with piecewise-quadratic motion over [0, horizon].
//
// A body's centre moves as p + v t + (a + gravity) t^2 / 2. Optional elastic walls
// (restitution 1) flip a velocity component when the centre reaches min + r or max - r
// on that axis while moving towards it. Optional acceleration changes replace the
// body's own acceleration at known times (gravity is always added). The exact
// trajectory is built by ccd/motion/trajectory.hpp. The file format is
// `ccdlab-scene/1`, read and written by ccd/scene/scene_io.hpp (docs/formats.md).
#include <ccd/geometry/vec3.hpp>

#include <optional>
#include <vector>

namespace ccd {

struct AccelerationChange {
  double t = 0.0;                    ///< time of the change, in (0, horizon)
  Vec3 acceleration{Vec3::Zero()};   ///< the body's own acceleration from t on
};

struct Body {
  double radius = 0.0;
  Vec3 position{Vec3::Zero()};
  Vec3 velocity{Vec3::Zero()};
  Vec3 acceleration{Vec3::Zero()};   ///< the body's own; gravity is added to it
  std::vector<AccelerationChange> acceleration_changes;  ///< sorted by t, strictly increasing
};

struct WallBox {
  Vec3 min{Vec3::Zero()};
  Vec3 max{Vec3::Zero()};
};

/// What a scene's motion needs, from least to most: the narrow phase and the bounds use
/// no more than this.
enum class MotionKind {
  Linear,                ///< no acceleration anywhere (walls may still reflect)
  SharedAcceleration,    ///< every body has the same constant acceleration (e.g. gravity)
  Quadratic,             ///< constant accelerations that differ between bodies
  PiecewiseQuadratic,    ///< accelerations change at known times
};

struct Scene {
  double horizon = 1.0;
  Vec3 gravity{Vec3::Zero()};
  std::optional<WallBox> box;
  std::vector<Body> bodies;

  /// The least motion model that describes this scene exactly.
  MotionKind motion_kind() const;
  /// Largest |own acceleration + gravity| over all bodies and all their changes.
  double max_acceleration() const;
};

const char* to_string(MotionKind kind);

}  // namespace ccd
