#include <ccd/scene/scene_io.hpp>

#include <ccd/geometry/double_double.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/scene/scene_field_paths.hpp>
#include <ccd/shape/convex_hull.hpp>
#include <ccd/shape/mass_properties.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

// The invariants of a scene (validate_scene; the list is in ccd/scene/scene_io.hpp), checked
// after reading and on scenes built in memory. Each check tests first and builds the field
// path only for a message: a million bodies would otherwise build tens of millions of
// strings no message uses.
namespace ccd {
namespace {

using Reader = JsonReader;

// The magnitude checks every number goes through, and the reach of a body over the horizon.
struct Limits {
  const Reader& r;
  const std::string limit = "1e+30";  // kMaxSceneMagnitude, as the message prints it

  void magnitude(double x, const std::string& f) const {
    if (!std::isfinite(x)) r.fail(f, "must be finite");
    if (std::fabs(x) > kMaxSceneMagnitude) r.fail(f, "magnitude above the limit " + limit);
  }
  void finite3(const Vec3& v, const std::string& f) const {
    for (int k = 0; k < 3; ++k) magnitude(v[k], f + "[" + std::to_string(k) + "]");
  }
  void positive(double x, const std::string& f) const {
    magnitude(x, f);
    if (!(x > 0.0)) r.fail(f, "must be > 0");
  }
  static bool within(double x) { return std::isfinite(x) && std::fabs(x) <= kMaxSceneMagnitude; }
  static bool within3(const Vec3& v) { return within(v.x()) && within(v.y()) && within(v.z()); }
  // How far a body can travel over the horizon (|v| T, |a + gravity| T^2 / 2), within the
  // limit, so that every position, distance and solver coefficient stays far from overflow.
  void reach(double travelled, const std::string& f, const char* what) const {
    if (!(travelled <= kMaxSceneMagnitude)) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", travelled);
      r.fail(f, std::string(what) + " is " + text + " m, above the limit " + limit + " m");
    }
  }
};
static_assert(kMaxSceneMagnitude == 1e30);

// The scenery of a scene (docs/scenery.md): every polygon (and mesh triangle) a valid
// static polygon, within the magnitude limit, and scenery only in a box that does not wrap
// around (wrap-around against scenery is not supported). Every shape may meet scenery.
template <class Magnitude>
void validate_scenery(const Scene& s, const Reader& r, Magnitude&& magnitude) {
  if (s.scenery.empty() && !s.scenery_mesh) return;
  const std::size_t mesh_triangles = s.scenery_mesh ? s.scenery_mesh->triangles.size() : 0;
  if (mesh_triangles > s.scenery.size())
    r.fail("scenery_mesh.triangles", "has more triangles than the scene has scenery polygons");
  const std::size_t polygons = s.scenery.size() - mesh_triangles;
  for (std::size_t i = 0; i < s.scenery.size(); ++i) {
    const bool mesh = i >= polygons;
    const std::string p = mesh ? "scenery_mesh.triangles[" + std::to_string(i - polygons) + "]"
                               : "scenery[" + std::to_string(i) + "].polygon";
    const StaticPolygon& poly = s.scenery[i];
    for (std::size_t k = 0; k < poly.vertices.size(); ++k)
      for (int c = 0; c < 3; ++c)
        magnitude(poly.vertices[k][c], p + "[" + std::to_string(k) + "][" + std::to_string(c) + "]");
    if (const auto d = polygon_defect(poly.vertices))
      r.fail(d->vertex < 0 ? p : p + "[" + std::to_string(d->vertex) + "]", d->reason);
    if (!(std::fabs(poly.normal.norm() - 1.0) <= 1e-12))
      r.fail(p, "normal must be the unit normal of the plane (ccd::polygon_from_vertices)");
  }
  if (s.box && s.box->any_wrap())
    r.fail("scenery", "static scenery in a box that wraps around (box.boundary) is not supported");
}

void validate_shapes(const Scene& s, const Reader& r, const Limits& lim) {
  for (std::size_t i = 0; i < s.shapes.size(); ++i) {
    const Shape& sh = s.shapes[i];
    const std::string p = shape_path(i);
    switch (sh.kind) {
      case ShapeKind::Sphere:
        lim.positive(sh.radius, p + ".radius");
        break;
      case ShapeKind::Capsule:
        lim.positive(sh.half_length, p + ".half_length");
        lim.positive(sh.radius, p + ".radius");
        break;
      case ShapeKind::Box:
        for (int k = 0; k < 3; ++k)
          lim.positive(sh.half_extents[k], p + ".half_extents[" + std::to_string(k) + "]");
        break;
      case ShapeKind::Hull: {
        for (std::size_t k = 0; k < sh.points.size(); ++k)
          lim.finite3(sh.points[k], p + ".points[" + std::to_string(k) + "]");
        if (const std::string why = hull_degeneracy(sh.points); !why.empty()) r.fail(p + ".points", why);
        break;
      }
    }
  }
}

// A free body without given inertia turns about its centre of mass, which its hull's origin
// must be (checked once per shape: `checked`).
template <class Path>
void validate_free_centre(const Scene& s, const Reader& r, const RigidBody& rb, std::vector<char>& checked,
                          Path p) {
  if (rb.spin != SpinModel::Free || rb.shape == kNoShape || rb.inertia) return;
  const Shape& sh = s.shapes[static_cast<std::size_t>(rb.shape)];
  if (sh.kind != ShapeKind::Hull || checked[static_cast<std::size_t>(rb.shape)]) return;
  checked[static_cast<std::size_t>(rb.shape)] = 1;
  // Counted before the mass properties are computed (points x faces time).
  if (sh.points.size() > kMaxMassPropertyPoints)
    r.fail(p() + ".spin", "free spin computes the mass properties of \"" + sh.name +
                              "\" from its points, at most " + std::to_string(kMaxMassPropertyPoints) +
                              " (it has " + std::to_string(sh.points.size()) +
                              "); give inertia, or fewer points");
  const Vec3 c = mass_properties(sh, 1.0).centre;
  if (!(c.norm() <= 1e-9 * sh.enclosing_radius())) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", c.x(), c.y(), c.z());
    r.fail(p() + ".spin", "free spin needs the hull's centre of mass at its origin; \"" + sh.name +
                              "\" has it at " + text + " (shift its points, or give inertia)");
  }
}

// A body's shape, orientation, spin and mass properties.
template <class Path>
void validate_rigid(const Scene& s, const Reader& r, const Limits& lim, const Body& b, const RigidBody& rb,
                    Path p) {
  if (rb.shape != kNoShape) {
    if (rb.shape < 0 || static_cast<std::size_t>(rb.shape) >= s.shapes.size())
      r.fail(p() + ".shape", "no such shape (index " + std::to_string(rb.shape) + ")");
    if (b.radius != s.shapes[static_cast<std::size_t>(rb.shape)].enclosing_radius())
      r.fail(p() + ".radius", "must be the shape's enclosing radius");
  }
  if (!Limits::within(b.radius)) lim.magnitude(b.radius, p() + ".radius");
  if (b.radius <= 0.0) r.fail(p() + ".radius", "must be > 0");
  for (int k = 0; k < 4; ++k)
    if (!Limits::within(rb.orientation.coeffs()[k]))
      lim.magnitude(rb.orientation.coeffs()[k], p() + ".orientation");
  if (!(std::fabs(rb.orientation.squaredNorm() - 1.0) <= 1e-12))
    r.fail(p() + ".orientation", "must be a unit quaternion");
  if (!Limits::within3(rb.angular_velocity)) lim.finite3(rb.angular_velocity, p() + ".angular_velocity");
  if (rb.mass) {
    lim.magnitude(*rb.mass, p() + ".mass");
    if (!(*rb.mass > 0.0)) r.fail(p() + ".mass", "must be > 0");
    if (rb.density) r.fail(p() + ".density", "not allowed with mass (give one of them)");
  }
  if (rb.density) {
    lim.magnitude(*rb.density, p() + ".density");
    if (!(*rb.density > 0.0)) r.fail(p() + ".density", "must be > 0");
  }
  if (rb.inertia) {
    const Vec3& I = *rb.inertia;
    lim.finite3(I, p() + ".inertia");
    for (int k = 0; k < 3; ++k)
      if (!(I[k] > 0.0))
        r.fail(p() + ".inertia[" + std::to_string(k) + "]", "must be > 0 (a principal moment)");
    for (int k = 0; k < 3; ++k)
      if (!(I[(k + 1) % 3] + I[(k + 2) % 3] >= I[k]))
        r.fail(p() + ".inertia", "violates the triangle inequality: inertia[" + std::to_string(k) +
                                     "] must be <= the sum of the other two moments");
  }
}

// A body's start in the box: inside on reflecting axes, centre in the cell on wrapped ones.
template <class Path>
void validate_in_box(const WallBox& box, const Reader& r, const Body& b, bool shaped, Path p) {
  for (int a = 0; a < 3; ++a) {
    if (box.wraps(a)) {
      // Periodic axis: the centre lies in [min, max] (the body may straddle the seam), and
      // the edge is at least twice the largest diameter, so that at most one periodic
      // image of another body can be within contact distance (ccd/scene/periodic.hpp).
      // A shaped body's radius is its enclosing radius: the same rule holds for it.
      if (b.position[a] < box.min[a] || b.position[a] > box.max[a])
        r.fail(p() + ".position[" + std::to_string(a) + "]",
               "centre must lie in [box.min, box.max] on a wrapped axis");
      if (!(4.0 * b.radius <= box.max[a] - box.min[a])) {
        if (shaped)
          r.fail(p() + ".shape",
                 "box edge on wrapped axis " + std::to_string(a) +
                     " must be at least twice the shape's enclosing diameter (4 x enclosing radius)");
        r.fail(p() + ".radius", "box edge on wrapped axis " + std::to_string(a) +
                                    " must be at least twice the body's diameter (4 x radius)");
      }
      continue;
    }
    if (b.position[a] - b.radius < box.min[a] || b.position[a] + b.radius > box.max[a])
      r.fail(p() + ".position", "body must start inside the box (centre at least radius from every wall)");
    // A body as wide as the box on an axis touches both walls at once: it cannot move
    // along that axis (it would reflect at both walls in zero time and leave the box).
    // Wall planes as the trajectory takes them: the exact sums, compared exactly.
    const Dd room = two_sum(box.max[a], -b.radius) - two_sum(box.min[a], b.radius);
    if (!(room.value() > 0.0) && b.velocity[a] != 0.0)
      r.fail(p() + ".velocity[" + std::to_string(a) + "]",
             "must be 0: the body fills the box on this axis (no room to move between the walls)");
  }
}

// A list of timed changes (`key`): times increasing strictly in (0, horizon), each vector
// (`value` of `get`) within the limits; `extra(change, path)` checks its reach.
template <class Change, class Path, class Get, class Extra>
void validate_changes(const Scene& s, const Reader& r, const Limits& lim, const std::vector<Change>& changes,
                      const char* key, const char* value, Path p, Get get, Extra extra) {
  double prev = 0.0;
  for (std::size_t k = 0; k < changes.size(); ++k) {
    const Change& c = changes[k];
    auto kp = [&] { return p() + "." + key + "[" + std::to_string(k) + "]"; };
    if (!std::isfinite(c.t) || c.t <= prev || c.t >= s.horizon)
      r.fail(kp() + ".t", "must increase strictly and lie in (0, horizon)");
    if (!Limits::within3(get(c))) lim.finite3(get(c), kp() + "." + value);
    extra(c, kp);
    prev = c.t;
  }
}

// A body's motion: start, velocity and acceleration within the limits, and its changes.
template <class Path>
void validate_motion(const Scene& s, const Reader& r, const Limits& lim, const Body& b, const RigidBody& rb,
                     Path p) {
  const double T = s.horizon;
  if (!Limits::within3(b.position)) lim.finite3(b.position, p() + ".position");
  if (!Limits::within3(b.velocity)) lim.finite3(b.velocity, p() + ".velocity");
  if (!Limits::within3(b.acceleration)) lim.finite3(b.acceleration, p() + ".acceleration");
  if (const double d = b.velocity.norm() * T; !(d <= kMaxSceneMagnitude))
    lim.reach(d, p() + ".velocity", "|velocity| * horizon");
  if (const double d = (b.acceleration + s.gravity).norm() * (0.5 * T * T); !(d <= kMaxSceneMagnitude))
    lim.reach(d, p() + ".acceleration", "|acceleration + gravity| * horizon^2 / 2");
  if (s.box) validate_in_box(*s.box, r, b, rb.shape != kNoShape, p);
  validate_changes(
      s, r, lim, b.acceleration_changes, "acceleration_changes", "acceleration", p,
      [](const AccelerationChange& c) { return c.acceleration; },
      [&](const AccelerationChange& c, auto kp) {
        if (const double d = (c.acceleration + s.gravity).norm() * (0.5 * T * T); !(d <= kMaxSceneMagnitude))
          lim.reach(d, kp() + ".acceleration", "|acceleration + gravity| * horizon^2 / 2");
      });
  validate_changes(
      s, r, lim, b.velocity_changes, "velocity_changes", "velocity", p,
      [](const VelocityChange& c) { return c.velocity; },
      [&](const VelocityChange& c, auto kp) {
        if (const double d = c.velocity.norm() * T; !(d <= kMaxSceneMagnitude))
          lim.reach(d, kp() + ".velocity", "|velocity| * horizon");
      });
  validate_changes(
      s, r, lim, rb.angular_velocity_changes, "angular_velocity_changes", "angular_velocity", p,
      [](const AngularVelocityChange& c) { return c.angular_velocity; },
      [](const AngularVelocityChange&, auto) {});
}

}  // namespace

void validate_scene(const Scene& s, const std::string& file) {
  Reader r{file};
  const Limits lim{r};
  lim.magnitude(s.horizon, "horizon");
  if (s.horizon <= 0.0) r.fail("horizon", "must be > 0");
  validate_scenery(s, r, [&](double x, const std::string& f) { lim.magnitude(x, f); });
  lim.finite3(s.gravity, "gravity");
  if (s.box) {
    lim.finite3(s.box->min, "box.min");
    lim.finite3(s.box->max, "box.max");
    for (int a = 0; a < 3; ++a)
      if (!(s.box->min[a] < s.box->max[a]))
        r.fail("box", "min must be < max on every axis (axis " + std::to_string(a) + ")");
  }
  validate_shapes(s, r, lim);
  static const RigidBody kDefaultRigid{};
  if (!s.rigid.empty() && s.rigid.size() != s.bodies.size())
    r.fail("bodies", "the shape and spin table has " + std::to_string(s.rigid.size()) + " entries for " +
                         std::to_string(s.bodies.size()) + " bodies");
  std::vector<char> centre_checked(s.shapes.size(), 0);  // a hull's centre of mass: once per shape
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    auto p = [i] { return body_path(i); };  // built only for a message
    const RigidBody& rb = s.rigid.empty() ? kDefaultRigid : s.rigid[i];
    validate_rigid(s, r, lim, b, rb, p);
    validate_free_centre(s, r, rb, centre_checked, p);
    validate_motion(s, r, lim, b, rb, p);
  }
}

}  // namespace ccd
