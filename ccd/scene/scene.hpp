#pragma once
// A scene: bodies (spheres, or shapes that spin) with piecewise-quadratic motion of their
// centres over [0, horizon].
//
// A body's centre moves as p + v t + (a + gravity) t^2 / 2. Optional elastic walls
// (restitution 1) flip a velocity component when the centre reaches min + r or max - r
// on that axis while moving towards it. Optional acceleration changes replace the
// body's own acceleration at known times (gravity is always added). The exact
// trajectory is built by ccd/motion/trajectory.hpp.
//
// Rigid bodies (docs/rigid_bodies.md): a body may name a shape of the scene's `shapes`
// (ccd/shape/shape.hpp); its `radius` is then the shape's enclosing radius, so walls,
// bounds and broad phases see it as that ball. Its orientation is a unit quaternion and
// its angular velocity is prescribed in the world frame, constant between its changes
// (ccd/motion/rotation.hpp); walls do not change the spin. The file formats are
// `ccdlab-scene/1` (spheres) and `ccdlab-scene/2` (shapes and spin), read and written by
// ccd/scene/scene_io.hpp (docs/formats.md).
#include <ccd/geometry/vec3.hpp>
#include <ccd/scene/scenery.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace ccd {

struct AccelerationChange {
  double t = 0.0;                    ///< time of the change, in (0, horizon)
  Vec3 acceleration{Vec3::Zero()};   ///< the body's own acceleration from t on
};

struct AngularVelocityChange {
  double t = 0.0;                        ///< time of the change, in (0, horizon)
  Vec3 angular_velocity{Vec3::Zero()};   ///< world frame, rad/s, from t on
};

struct Body {
  /// Plain sphere: its radius. Shaped body: the shape's enclosing radius (set by the reader
  /// and by Scene::add_rigid_body).
  double radius = 0.0;
  Vec3 position{Vec3::Zero()};
  Vec3 velocity{Vec3::Zero()};
  Vec3 acceleration{Vec3::Zero()};   ///< the body's own; gravity is added to it
  std::vector<AccelerationChange> acceleration_changes;  ///< sorted by t, strictly increasing
};

/// RigidBody::shape of a plain sphere (no entry in Scene::shapes; its size is Body::radius).
inline constexpr std::int32_t kNoShape = -1;

/// How a shaped body turns (docs/rigid_bodies.md): `Prescribed`, the angular velocity is
/// given and constant between its changes; `Free`, torque-free: the angular momentum is
/// constant between changes (ccd/motion/free_rotation.hpp), the angular velocity given at
/// t = 0 and at each change.
enum class SpinModel : std::uint8_t { Prescribed, Free };

/// A body's shape and spin: a side table of the scene (Scene::rigid), empty for sphere
/// scenes, so Body keeps its layout.
struct RigidBody {
  std::int32_t shape = kNoShape;     ///< index into Scene::shapes, or kNoShape
  Eigen::Quaterniond orientation{Eigen::Quaterniond::Identity()};  ///< unit, body to world
  Vec3 angular_velocity{Vec3::Zero()};  ///< world frame, rad/s
  std::vector<AngularVelocityChange> angular_velocity_changes;  ///< sorted by t, strictly increasing
  SpinModel spin = SpinModel::Prescribed;
  /// Mass properties (ccd/shape/mass_properties.hpp): at most one of mass (kg) and density
  /// (kg/m^3), default density 1000; `inertia`, when given, the principal moments (kg m^2)
  /// about the body axes, replacing the shape's.
  std::optional<double> mass;
  std::optional<double> density;
  std::optional<Vec3> inertia;

  /// Orientation, spin or spin changes differ from the defaults.
  bool spins() const {
    return !angular_velocity.isZero(0.0) || !angular_velocity_changes.empty() ||
           orientation.coeffs() != Eigen::Quaterniond::Identity().coeffs() || spin != SpinModel::Prescribed ||
           mass || density || inertia;
  }
};

/// What a face pair of the box does to a body's centre on one axis.
enum class Boundary : std::uint8_t {
  Reflect,  ///< elastic walls at min + r and max - r (restitution 1)
  Wrap,     ///< periodic: a centre reaching max re-enters at min (and back), velocity kept
};

/// "reflect", "wrap".
const char* to_string(Boundary b);

struct WallBox {
  Vec3 min{Vec3::Zero()};
  Vec3 max{Vec3::Zero()};
  /// Per axis; Reflect on every axis by default (ccd/scene/periodic.hpp for Wrap).
  std::array<Boundary, 3> boundary{Boundary::Reflect, Boundary::Reflect, Boundary::Reflect};

  bool wraps(int axis) const { return boundary[static_cast<std::size_t>(axis)] == Boundary::Wrap; }
  bool any_wrap() const { return wraps(0) || wraps(1) || wraps(2); }
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
  std::vector<Shape> shapes;  ///< empty for sphere scenes
  std::vector<Body> bodies;
  /// Empty (every body a plain sphere without spin), or one entry per body.
  std::vector<RigidBody> rigid;
  /// Static polygons (ccd/scene/scenery.hpp): empty for a scene without scenery. The
  /// `scenery` polygons of the file, then one triangle per mesh triangle.
  std::vector<StaticPolygon> scenery;
  /// The mesh the last scenery_mesh->triangles.size() entries of `scenery` came from (kept
  /// so that the scene is written back as read); empty when there is none.
  std::optional<SceneryMesh> scenery_mesh;

  /// Some body names a shape or spins: the scene needs `ccdlab-scene/2`.
  bool is_rigid() const;
  /// Some body has a shape that is not a sphere (the narrow phase needs the generic entry).
  bool has_non_spheres() const;
  /// The kind of body i's shape (Sphere for a plain sphere).
  ShapeKind kind(std::size_t i) const {
    return rigid.empty() || rigid[i].shape == kNoShape ? ShapeKind::Sphere
                                                        : shapes[static_cast<std::size_t>(rigid[i].shape)].kind;
  }
  /// Body i's principal moments (kg m^2) and axes (columns, body frame): the explicit
  /// `inertia`, else the shape's (or plain sphere's) at its mass or density.
  void principal_inertia(std::size_t i, Vec3& moments, Eigen::Matrix3d& axes) const;
  /// Body i's shape and spin (the defaults when `rigid` is empty).
  RigidBody rigid_body(std::size_t i) const { return rigid.empty() ? RigidBody{} : rigid[i]; }
  /// Appends a body with shape and spin `r`: body.radius becomes the shape's enclosing
  /// radius (unless r.shape is kNoShape); `rigid` is filled with defaults first if empty.
  void add_rigid_body(Body body, RigidBody r);
  /// Some axis of the box wraps around (periodic boundary).
  bool wraps() const { return box && box->any_wrap(); }
  /// The least motion model that describes this scene exactly.
  MotionKind motion_kind() const;
  /// Largest |own acceleration + gravity| over all bodies and all their changes.
  double max_acceleration() const;
};

const char* to_string(MotionKind kind);
const char* to_string(SpinModel model);

}  // namespace ccd
