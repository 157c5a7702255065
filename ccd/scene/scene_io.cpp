#include <ccd/scene/scene_io.hpp>

#include <ccd/io/atomic_file.hpp>
#include <ccd/geometry/double_double.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/shape/convex_hull.hpp>
#include <ccd/shape/mass_properties.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>
#include <cstdio>

namespace ccd {
namespace {

using nlohmann::json;

using Reader = JsonReader;

std::string body_path(std::size_t i) { return "bodies[" + std::to_string(i) + "]"; }
std::string shape_path(std::size_t i) { return "shapes[" + std::to_string(i) + "]"; }

// Largest accepted | |q| - 1 | of an orientation as read; it is then normalised.
constexpr double kQuaternionTolerance = 1e-6;
// An orientation whose |q|^2 is within this of 1 is already a normalised quaternion (a
// quaternion divided by its norm lands within a few units of rounding of 1) and is kept
// bit for bit: normalising again would move its last bits, so a scene written from memory
// (a generator's) would read back as a different scene, with another digest.
constexpr double kNormalisedTolerance = 16.0 * std::numeric_limits<double>::epsilon();

Boundary boundary_name(const Reader& r, const json& v, const std::string& p) {
  const std::string name = r.string(v, p);
  if (name == "reflect") return Boundary::Reflect;
  if (name == "wrap") return Boundary::Wrap;
  r.fail(p, "must be \"reflect\" or \"wrap\"");
}

// "box.boundary": one name for every axis, or an array of three.
std::array<Boundary, 3> boundary_from_json(const Reader& r, const json& v) {
  if (v.is_string()) {
    const Boundary b = boundary_name(r, v, "box.boundary");
    return {b, b, b};
  }
  if (!v.is_array() || v.size() != 3)
    r.fail("box.boundary", "must be \"reflect\", \"wrap\" or an array of three of them (one per axis)");
  std::array<Boundary, 3> out{};
  for (std::size_t k = 0; k < 3; ++k) out[k] = boundary_name(r, v[k], "box.boundary[" + std::to_string(k) + "]");
  return out;
}

Shape shape_from_json(const Reader& r, const json& o, const std::string& p) {
  if (!o.is_object()) r.fail(p, "must be an object with name and kind");
  Shape s;
  s.name = r.string(r.require(o, "name", p), p + ".name");
  if (s.name.empty()) r.fail(p + ".name", "must not be empty");
  const std::string kind = r.string(r.require(o, "kind", p), p + ".kind");
  const auto k = shape_kind_from_string(kind);
  if (!k) r.fail(p + ".kind", "unknown shape kind \"" + kind + "\" (sphere, capsule, box, hull)");
  s.kind = *k;
  switch (s.kind) {
    case ShapeKind::Sphere: r.only_fields(o, p, {"name", "kind", "radius"}); break;
    case ShapeKind::Capsule: r.only_fields(o, p, {"name", "kind", "half_length", "radius"}); break;
    case ShapeKind::Box: r.only_fields(o, p, {"name", "kind", "half_extents"}); break;
    case ShapeKind::Hull: r.only_fields(o, p, {"name", "kind", "points"}); break;
  }
  switch (s.kind) {
    case ShapeKind::Sphere: s.radius = r.number(r.require(o, "radius", p), p + ".radius"); break;
    case ShapeKind::Capsule:
      s.half_length = r.number(r.require(o, "half_length", p), p + ".half_length");
      s.radius = r.number(r.require(o, "radius", p), p + ".radius");
      break;
    case ShapeKind::Box: s.half_extents = r.vec3(r.require(o, "half_extents", p), p + ".half_extents"); break;
    case ShapeKind::Hull: {
      const json& pts = r.require(o, "points", p);
      if (!pts.is_array()) r.fail(p + ".points", "must be an array of [x, y, z] points");
      for (std::size_t i = 0; i < pts.size(); ++i)
        s.points.push_back(r.vec3(pts[i], p + ".points[" + std::to_string(i) + "]"));
      break;
    }
  }
  s.build_points();
  return s;
}

json shape_to_json(const Shape& s) {
  auto v = [](const Vec3& x) { return json::array({x.x(), x.y(), x.z()}); };
  json j = {{"name", s.name}, {"kind", std::string(to_string(s.kind))}};
  switch (s.kind) {
    case ShapeKind::Sphere: j["radius"] = s.radius; break;
    case ShapeKind::Capsule:
      j["half_length"] = s.half_length;
      j["radius"] = s.radius;
      break;
    case ShapeKind::Box: j["half_extents"] = v(s.half_extents); break;
    case ShapeKind::Hull: {
      json pts = json::array();
      for (const Vec3& q : s.points) pts.push_back(v(q));
      j["points"] = std::move(pts);
      break;
    }
  }
  return j;
}

}  // namespace

namespace {

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

}  // namespace

Scene scene_from_json(const json& j, const std::string& file) {
  Reader r{file};
  if (!j.is_object()) r.fail("", "a scene must be a JSON object");
  // Version-2 names are known in both versions: a version-1 file that uses one is told
  // it needs version 2 (below), not that the field is unknown.
  r.only_fields(j, "", {"format", "horizon", "gravity", "box", "shapes", "bodies", "scenery", "scenery_mesh"});
  const json& format = r.require(j, "format", "");
  if (!format.is_string() ||
      (format.get<std::string>() != kSceneFormatV1 && format.get<std::string>() != kSceneFormat))
    r.fail("format", "must be \"ccdlab-scene/1\" or \"ccdlab-scene/2\"");
  const bool v2 = format.get<std::string>() == kSceneFormat;
  Scene s;
  s.horizon = r.number(r.require(j, "horizon", ""), "horizon");
  s.gravity = r.optional_vec3(j, "gravity", "");
  if (auto it = j.find("box"); it != j.end() && !it->is_null()) {
    if (!it->is_object()) r.fail("box", "must be an object with min and max");
    r.only_fields(*it, "box", {"min", "max", "boundary"});
    WallBox box;
    box.min = r.vec3(r.require(*it, "min", "box"), "box.min");
    box.max = r.vec3(r.require(*it, "max", "box"), "box.max");
    if (auto b = it->find("boundary"); b != it->end()) box.boundary = boundary_from_json(r, *b);
    s.box = box;
  }
  std::unordered_map<std::string, std::size_t> shape_index;  // name -> index: linear in the shapes
  if (auto it = j.find("shapes"); it != j.end()) {
    if (!v2) r.fail("shapes", "needs format \"ccdlab-scene/2\"");
    if (!it->is_array()) r.fail("shapes", "must be an array");
    for (std::size_t i = 0; i < it->size(); ++i) {
      Shape sh = shape_from_json(r, (*it)[i], shape_path(i));
      const auto [at, added] = shape_index.emplace(sh.name, i);
      if (!added) r.fail(shape_path(i) + ".name", "\"" + sh.name + "\" is already the name of " + shape_path(at->second));
      s.shapes.push_back(std::move(sh));
    }
  }
  const json& bodies = r.require(j, "bodies", "");
  if (!bodies.is_array()) r.fail("bodies", "must be an array");
  s.bodies.reserve(bodies.size());
  if (v2) s.rigid.reserve(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const json& b = bodies[i];
    const std::string p = body_path(i);
    if (!b.is_object()) r.fail(p, "must be an object");
    r.only_fields(b, p, {"radius", "position", "velocity", "acceleration", "acceleration_changes", "velocity_changes", "shape",
                         "orientation", "angular_velocity", "angular_velocity_changes", "spin", "mass", "density",
                         "inertia"});
    Body body;
    RigidBody rigid;
    if (auto it = b.find("shape"); it != b.end()) {
      if (!v2) r.fail(p + ".shape", "needs format \"ccdlab-scene/2\"");
      const std::string name = r.string(*it, p + ".shape");
      const auto found = shape_index.find(name);
      if (found == shape_index.end()) r.fail(p + ".shape", "unknown shape \"" + name + "\" (not in shapes)");
      if (b.contains("radius")) r.fail(p + ".radius", "not allowed with shape (the shape gives the size)");
      rigid.shape = static_cast<std::int32_t>(found->second);
    } else {
      body.radius = r.number(r.require(b, "radius", p), p + ".radius");
    }
    body.position = r.vec3(r.require(b, "position", p), p + ".position");
    body.velocity = r.optional_vec3(b, "velocity", p);
    body.acceleration = r.optional_vec3(b, "acceleration", p);
    if (auto it = b.find("acceleration_changes"); it != b.end()) {
      const std::string cp = p + ".acceleration_changes";
      if (!it->is_array()) r.fail(cp, "must be an array");
      for (std::size_t k = 0; k < it->size(); ++k) {
        const json& c = (*it)[k];
        const std::string kp = cp + "[" + std::to_string(k) + "]";
        if (!c.is_object()) r.fail(kp, "must be an object with t and acceleration");
        r.only_fields(c, kp, {"t", "acceleration"});
        AccelerationChange ch;
        ch.t = r.number(r.require(c, "t", kp), kp + ".t");
        ch.acceleration = r.vec3(r.require(c, "acceleration", kp), kp + ".acceleration");
        body.acceleration_changes.push_back(ch);
      }
    }
    if (auto it = b.find("velocity_changes"); it != b.end()) {
      const std::string cp = p + ".velocity_changes";
      if (!it->is_array()) r.fail(cp, "must be an array");
      for (std::size_t k = 0; k < it->size(); ++k) {
        const json& c = (*it)[k];
        const std::string kp = cp + "[" + std::to_string(k) + "]";
        if (!c.is_object()) r.fail(kp, "must be an object with t and velocity");
        r.only_fields(c, kp, {"t", "velocity"});
        VelocityChange ch;
        ch.t = r.number(r.require(c, "t", kp), kp + ".t");
        ch.velocity = r.vec3(r.require(c, "velocity", kp), kp + ".velocity");
        body.velocity_changes.push_back(ch);
      }
    }
    for (const char* key : {"orientation", "angular_velocity", "angular_velocity_changes", "spin", "mass", "density",
                            "inertia"})
      if (!v2 && b.contains(key)) r.fail(p + "." + key, "needs format \"ccdlab-scene/2\"");
    if (auto it = b.find("orientation"); it != b.end()) {
      const std::string op = p + ".orientation";
      if (!it->is_array() || it->size() != 4) r.fail(op, "must be a quaternion [w, x, y, z]");
      double q[4];
      for (std::size_t k = 0; k < 4; ++k) q[k] = r.number((*it)[k], op + "[" + std::to_string(k) + "]");
      Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
      const double n = quat.norm();
      if (!(std::fabs(n - 1.0) <= kQuaternionTolerance))
        r.fail(op, "must be a unit quaternion (|q| is " + std::to_string(n) + ")");
      if (!(std::fabs(quat.squaredNorm() - 1.0) <= kNormalisedTolerance)) quat.normalize();
      rigid.orientation = quat;
    }
    rigid.angular_velocity = r.optional_vec3(b, "angular_velocity", p);
    if (auto it = b.find("angular_velocity_changes"); it != b.end()) {
      const std::string cp = p + ".angular_velocity_changes";
      if (!it->is_array()) r.fail(cp, "must be an array");
      for (std::size_t k = 0; k < it->size(); ++k) {
        const json& c = (*it)[k];
        const std::string kp = cp + "[" + std::to_string(k) + "]";
        if (!c.is_object()) r.fail(kp, "must be an object with t and angular_velocity");
        r.only_fields(c, kp, {"t", "angular_velocity"});
        AngularVelocityChange ch;
        ch.t = r.number(r.require(c, "t", kp), kp + ".t");
        ch.angular_velocity = r.vec3(r.require(c, "angular_velocity", kp), kp + ".angular_velocity");
        rigid.angular_velocity_changes.push_back(ch);
      }
    }
    if (auto it = b.find("spin"); it != b.end()) {
      const std::string model = r.string(*it, p + ".spin");
      if (model == "free")
        rigid.spin = SpinModel::Free;
      else if (model != "prescribed")
        r.fail(p + ".spin", "unknown spin \"" + model + "\" (prescribed, free)");
    }
    if (auto it = b.find("mass"); it != b.end()) rigid.mass = r.number(*it, p + ".mass");
    if (auto it = b.find("density"); it != b.end()) rigid.density = r.number(*it, p + ".density");
    if (auto it = b.find("inertia"); it != b.end()) rigid.inertia = r.vec3(*it, p + ".inertia");
    if (rigid.shape != kNoShape) body.radius = s.shapes[static_cast<std::size_t>(rigid.shape)].enclosing_radius();
    s.bodies.push_back(std::move(body));
    if (v2) s.rigid.push_back(std::move(rigid));
  }
  // Static scenery (docs/scenery.md): polygons, then the mesh's triangles.
  if (auto it = j.find("scenery"); it != j.end()) {
    if (!v2) r.fail("scenery", "needs format \"ccdlab-scene/2\"");
    if (!it->is_array()) r.fail("scenery", "must be an array of {\"polygon\": [[x, y, z], ...]}");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string p = "scenery[" + std::to_string(i) + "]";
      const json& o = (*it)[i];
      if (!o.is_object()) r.fail(p, "must be an object {\"polygon\": [[x, y, z], ...]}");
      r.only_fields(o, p, {"polygon"});
      const json& poly = r.require(o, "polygon", p);
      if (!poly.is_array()) r.fail(p + ".polygon", "must be an array of [x, y, z] vertices");
      std::vector<Vec3> vs;
      for (std::size_t k = 0; k < poly.size(); ++k) vs.push_back(r.vec3(poly[k], p + ".polygon[" + std::to_string(k) + "]"));
      s.scenery.push_back(polygon_from_vertices(std::move(vs)));
    }
  }
  if (auto it = j.find("scenery_mesh"); it != j.end()) {
    if (!v2) r.fail("scenery_mesh", "needs format \"ccdlab-scene/2\"");
    if (!it->is_object()) r.fail("scenery_mesh", "must be an object with vertices and triangles");
    r.only_fields(*it, "scenery_mesh", {"vertices", "triangles"});
    SceneryMesh mesh;
    const json& vs = r.require(*it, "vertices", "scenery_mesh");
    if (!vs.is_array()) r.fail("scenery_mesh.vertices", "must be an array of [x, y, z]");
    for (std::size_t k = 0; k < vs.size(); ++k)
      mesh.vertices.push_back(r.vec3(vs[k], "scenery_mesh.vertices[" + std::to_string(k) + "]"));
    const json& ts = r.require(*it, "triangles", "scenery_mesh");
    if (!ts.is_array()) r.fail("scenery_mesh.triangles", "must be an array of [i, j, k] vertex indices");
    for (std::size_t k = 0; k < ts.size(); ++k) {
      const std::string p = "scenery_mesh.triangles[" + std::to_string(k) + "]";
      if (!ts[k].is_array() || ts[k].size() != 3) r.fail(p, "must be an array of 3 vertex indices");
      std::array<std::uint32_t, 3> tri{};
      for (std::size_t c = 0; c < 3; ++c) {
        const std::string f = p + "[" + std::to_string(c) + "]";
        tri[c] = r.index(ts[k][c], f);
        if (tri[c] >= mesh.vertices.size())
          r.fail(f, "vertex index " + std::to_string(tri[c]) + " out of range (the mesh has " +
                        std::to_string(mesh.vertices.size()) + " vertices)");
      }
      mesh.triangles.push_back(tri);
      s.scenery.push_back(
          polygon_from_vertices({mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]}));
    }
    s.scenery_mesh = std::move(mesh);
  }
  // A version-2 file of plain spheres without spin is a sphere scene: no side table.
  if (std::none_of(s.rigid.begin(), s.rigid.end(), [](const RigidBody& x) { return x.shape != kNoShape || x.spins(); }))
    s.rigid.clear();
  validate_scene(s, file);
  return s;
}

void validate_scene(const Scene& s, const std::string& file) {
  Reader r{file};
  const std::string limit = "1e+30";  // kMaxSceneMagnitude, as the message prints it
  static_assert(kMaxSceneMagnitude == 1e30);
  auto magnitude = [&](double x, const std::string& f) {
    if (!std::isfinite(x)) r.fail(f, "must be finite");
    if (std::fabs(x) > kMaxSceneMagnitude) r.fail(f, "magnitude above the limit " + limit);
  };
  auto finite3 = [&](const Vec3& v, const std::string& f) {
    for (int k = 0; k < 3; ++k) magnitude(v[k], f + "[" + std::to_string(k) + "]");
  };
  magnitude(s.horizon, "horizon");
  if (s.horizon <= 0.0) r.fail("horizon", "must be > 0");
  validate_scenery(s, r, magnitude);
  finite3(s.gravity, "gravity");
  if (s.box) {
    finite3(s.box->min, "box.min");
    finite3(s.box->max, "box.max");
    for (int a = 0; a < 3; ++a)
      if (!(s.box->min[a] < s.box->max[a]))
        r.fail("box", "min must be < max on every axis (axis " + std::to_string(a) + ")");
  }
  for (std::size_t i = 0; i < s.shapes.size(); ++i) {
    const Shape& sh = s.shapes[i];
    const std::string p = shape_path(i);
    auto positive = [&](double x, const std::string& f) {
      magnitude(x, f);
      if (!(x > 0.0)) r.fail(f, "must be > 0");
    };
    switch (sh.kind) {
      case ShapeKind::Sphere: positive(sh.radius, p + ".radius"); break;
      case ShapeKind::Capsule:
        positive(sh.half_length, p + ".half_length");
        positive(sh.radius, p + ".radius");
        break;
      case ShapeKind::Box:
        for (int k = 0; k < 3; ++k) positive(sh.half_extents[k], p + ".half_extents[" + std::to_string(k) + "]");
        break;
      case ShapeKind::Hull: {
        for (std::size_t k = 0; k < sh.points.size(); ++k) finite3(sh.points[k], p + ".points[" + std::to_string(k) + "]");
        if (const std::string why = hull_degeneracy(sh.points); !why.empty()) r.fail(p + ".points", why);
        break;
      }
    }
  }
  const double T = s.horizon;
  // How far a body can travel over the horizon: |v| T and |a + gravity| T^2 / 2 (every
  // acceleration it takes), each within the limit, so that every position, distance and
  // solver coefficient stays far from overflow.
  auto reach = [&](double travelled, const std::string& f, const char* what) {
    if (!(travelled <= kMaxSceneMagnitude)) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", travelled);
      r.fail(f, std::string(what) + " is " + text + " m, above the limit " + limit + " m");
    }
  };
  auto within = [](double x) { return std::isfinite(x) && std::fabs(x) <= kMaxSceneMagnitude; };
  auto within3 = [&](const Vec3& v) { return within(v.x()) && within(v.y()) && within(v.z()); };
  static const RigidBody kDefaultRigid{};
  if (!s.rigid.empty() && s.rigid.size() != s.bodies.size())
    r.fail("bodies", "the shape and spin table has " + std::to_string(s.rigid.size()) + " entries for " +
                         std::to_string(s.bodies.size()) + " bodies");
  std::vector<char> centre_checked(s.shapes.size(), 0);  // a hull's centre of mass: once per shape
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    // Field names are built only for a message (a million bodies would otherwise build tens
    // of millions of strings no message uses): each check tests first, then names.
    auto p = [i] { return body_path(i); };
    const RigidBody& rb = s.rigid.empty() ? kDefaultRigid : s.rigid[i];
    if (rb.shape != kNoShape) {
      if (rb.shape < 0 || static_cast<std::size_t>(rb.shape) >= s.shapes.size())
        r.fail(p() + ".shape", "no such shape (index " + std::to_string(rb.shape) + ")");
      if (b.radius != s.shapes[static_cast<std::size_t>(rb.shape)].enclosing_radius())
        r.fail(p() + ".radius", "must be the shape's enclosing radius");
    }
    if (!within(b.radius)) magnitude(b.radius, p() + ".radius");
    if (b.radius <= 0.0) r.fail(p() + ".radius", "must be > 0");
    for (int k = 0; k < 4; ++k)
      if (!within(rb.orientation.coeffs()[k])) magnitude(rb.orientation.coeffs()[k], p() + ".orientation");
    if (!(std::fabs(rb.orientation.squaredNorm() - 1.0) <= 1e-12)) r.fail(p() + ".orientation", "must be a unit quaternion");
    if (!within3(rb.angular_velocity)) finite3(rb.angular_velocity, p() + ".angular_velocity");
    if (rb.mass) {
      magnitude(*rb.mass, p() + ".mass");
      if (!(*rb.mass > 0.0)) r.fail(p() + ".mass", "must be > 0");
      if (rb.density) r.fail(p() + ".density", "not allowed with mass (give one of them)");
    }
    if (rb.density) {
      magnitude(*rb.density, p() + ".density");
      if (!(*rb.density > 0.0)) r.fail(p() + ".density", "must be > 0");
    }
    if (rb.inertia) {
      const Vec3& I = *rb.inertia;
      finite3(I, p() + ".inertia");
      for (int k = 0; k < 3; ++k)
        if (!(I[k] > 0.0)) r.fail(p() + ".inertia[" + std::to_string(k) + "]", "must be > 0 (a principal moment)");
      for (int k = 0; k < 3; ++k)
        if (!(I[(k + 1) % 3] + I[(k + 2) % 3] >= I[k]))
          r.fail(p() + ".inertia", "violates the triangle inequality: inertia[" + std::to_string(k) +
                                     "] must be <= the sum of the other two moments");
    }
    if (rb.spin == SpinModel::Free && rb.shape != kNoShape && !rb.inertia) {
      // A free body turns about its centre of mass, which the shape's origin must be.
      const Shape& sh = s.shapes[static_cast<std::size_t>(rb.shape)];
      if (sh.kind == ShapeKind::Hull && !centre_checked[static_cast<std::size_t>(rb.shape)]) {
        centre_checked[static_cast<std::size_t>(rb.shape)] = 1;
        // Counted before the mass properties are computed (points x faces time).
        if (sh.points.size() > kMaxMassPropertyPoints)
          r.fail(p() + ".spin", "free spin computes the mass properties of \"" + sh.name + "\" from its points, at most " +
                                  std::to_string(kMaxMassPropertyPoints) + " (it has " +
                                  std::to_string(sh.points.size()) + "); give inertia, or fewer points");
        const Vec3 c = mass_properties(sh, 1.0).centre;
        if (!(c.norm() <= 1e-9 * sh.enclosing_radius())) {
          char text[96];
          std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", c.x(), c.y(), c.z());
          r.fail(p() + ".spin", "free spin needs the hull's centre of mass at its origin; \"" + sh.name + "\" has it at " +
                                  text + " (shift its points, or give inertia)");
        }
      }
    }
    if (!within3(b.position)) finite3(b.position, p() + ".position");
    if (!within3(b.velocity)) finite3(b.velocity, p() + ".velocity");
    if (!within3(b.acceleration)) finite3(b.acceleration, p() + ".acceleration");
    if (const double d = b.velocity.norm() * T; !(d <= kMaxSceneMagnitude))
      reach(d, p() + ".velocity", "|velocity| * horizon");
    if (const double d = (b.acceleration + s.gravity).norm() * (0.5 * T * T); !(d <= kMaxSceneMagnitude))
      reach(d, p() + ".acceleration", "|acceleration + gravity| * horizon^2 / 2");
    if (s.box) {
      for (int a = 0; a < 3; ++a) {
        if (s.box->wraps(a)) {
          // Periodic axis: the centre lies in [min, max] (the body may straddle the seam), and
          // the edge is at least twice the largest diameter, so that at most one periodic
          // image of another body can be within contact distance (ccd/scene/periodic.hpp).
          // A shaped body's radius is its enclosing radius: the same rule holds for it.
          if (b.position[a] < s.box->min[a] || b.position[a] > s.box->max[a])
            r.fail(p() + ".position[" + std::to_string(a) + "]",
                   "centre must lie in [box.min, box.max] on a wrapped axis");
          if (!(4.0 * b.radius <= s.box->max[a] - s.box->min[a])) {
            if (rb.shape != kNoShape)
              r.fail(p() + ".shape", "box edge on wrapped axis " + std::to_string(a) +
                                       " must be at least twice the shape's enclosing diameter (4 x enclosing radius)");
            r.fail(p() + ".radius", "box edge on wrapped axis " + std::to_string(a) +
                                      " must be at least twice the body's diameter (4 x radius)");
          }
          continue;
        }
        if (b.position[a] - b.radius < s.box->min[a] || b.position[a] + b.radius > s.box->max[a])
          r.fail(p() + ".position", "body must start inside the box (centre at least radius from every wall)");
        // A body as wide as the box on an axis touches both walls at once: it cannot move
        // along that axis (it would reflect at both walls in zero time and leave the box).
        // Wall planes as the trajectory takes them: the exact sums, compared exactly.
        const Dd room = two_sum(s.box->max[a], -b.radius) - two_sum(s.box->min[a], b.radius);
        if (!(room.value() > 0.0) && b.velocity[a] != 0.0)
          r.fail(p() + ".velocity[" + std::to_string(a) + "]",
                 "must be 0: the body fills the box on this axis (no room to move between the walls)");
      }
    }
    double prev = 0.0;
    for (std::size_t k = 0; k < b.acceleration_changes.size(); ++k) {
      const AccelerationChange& c = b.acceleration_changes[k];
      auto kp = [&] { return p() + ".acceleration_changes[" + std::to_string(k) + "]"; };
      if (!std::isfinite(c.t) || c.t <= prev || c.t >= s.horizon)
        r.fail(kp() + ".t", "must increase strictly and lie in (0, horizon)");
      if (!within3(c.acceleration)) finite3(c.acceleration, kp() + ".acceleration");
      if (const double d = (c.acceleration + s.gravity).norm() * (0.5 * T * T); !(d <= kMaxSceneMagnitude))
        reach(d, kp() + ".acceleration", "|acceleration + gravity| * horizon^2 / 2");
      prev = c.t;
    }
    prev = 0.0;
    for (std::size_t k = 0; k < b.velocity_changes.size(); ++k) {
      const VelocityChange& c = b.velocity_changes[k];
      auto kp = [&] { return p() + ".velocity_changes[" + std::to_string(k) + "]"; };
      if (!std::isfinite(c.t) || c.t <= prev || c.t >= s.horizon)
        r.fail(kp() + ".t", "must increase strictly and lie in (0, horizon)");
      if (!within3(c.velocity)) finite3(c.velocity, kp() + ".velocity");
      if (const double d = c.velocity.norm() * T; !(d <= kMaxSceneMagnitude)) reach(d, kp() + ".velocity", "|velocity| * horizon");
      prev = c.t;
    }
    prev = 0.0;
    for (std::size_t k = 0; k < rb.angular_velocity_changes.size(); ++k) {
      const AngularVelocityChange& c = rb.angular_velocity_changes[k];
      auto kp = [&] { return p() + ".angular_velocity_changes[" + std::to_string(k) + "]"; };
      if (!std::isfinite(c.t) || c.t <= prev || c.t >= s.horizon)
        r.fail(kp() + ".t", "must increase strictly and lie in (0, horizon)");
      if (!within3(c.angular_velocity)) finite3(c.angular_velocity, kp() + ".angular_velocity");
      prev = c.t;
    }
  }
}

Scene load_scene(const std::string& path) {
  if (is_binary_scene_file(path)) return load_binary_scene(path);
  return scene_from_json(read_json_file(path), path);
}

json scene_to_json(const Scene& s) {
  auto v = [](const Vec3& x) { return json::array({x.x(), x.y(), x.z()}); };
  json j;
  const bool v2 = s.is_rigid() || !s.scenery.empty();
  j["format"] = v2 ? kSceneFormat : kSceneFormatV1;
  j["horizon"] = s.horizon;
  j["gravity"] = v(s.gravity);
  if (s.box) {
    j["box"] = {{"min", v(s.box->min)}, {"max", v(s.box->max)}};
    // Written only when some axis wraps, so reflecting scenes and their digests stay as they were.
    if (s.box->any_wrap()) {
      json b = json::array();
      for (Boundary x : s.box->boundary) b.push_back(to_string(x));
      j["box"]["boundary"] = std::move(b);
    }
  }
  if (v2) {
    json shapes = json::array();
    for (const Shape& sh : s.shapes) shapes.push_back(shape_to_json(sh));
    j["shapes"] = std::move(shapes);
  }
  json bodies = json::array();
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    const RigidBody rb = s.rigid_body(i);
    json jb = {{"position", v(b.position)}, {"velocity", v(b.velocity)}, {"acceleration", v(b.acceleration)}};
    if (rb.shape == kNoShape)
      jb["radius"] = b.radius;
    else
      jb["shape"] = s.shapes[static_cast<std::size_t>(rb.shape)].name;
    if (!b.acceleration_changes.empty()) {
      json ch = json::array();
      for (const AccelerationChange& c : b.acceleration_changes)
        ch.push_back({{"t", c.t}, {"acceleration", v(c.acceleration)}});
      jb["acceleration_changes"] = ch;
    }
    if (!b.velocity_changes.empty()) {  // written only when present: other scenes keep their digests
      json ch = json::array();
      for (const VelocityChange& c : b.velocity_changes) ch.push_back({{"t", c.t}, {"velocity", v(c.velocity)}});
      jb["velocity_changes"] = ch;
    }
    if (v2) {
      const Eigen::Quaterniond& q = rb.orientation;
      jb["orientation"] = json::array({q.w(), q.x(), q.y(), q.z()});
      jb["angular_velocity"] = v(rb.angular_velocity);
      // Only what differs from the defaults, so that version-2 files without these fields
      // are written (and digested) as before.
      if (rb.spin != SpinModel::Prescribed) jb["spin"] = to_string(rb.spin);
      if (rb.mass) jb["mass"] = *rb.mass;
      if (rb.density) jb["density"] = *rb.density;
      if (rb.inertia) jb["inertia"] = v(*rb.inertia);
      if (!rb.angular_velocity_changes.empty()) {
        json ch = json::array();
        for (const AngularVelocityChange& c : rb.angular_velocity_changes)
          ch.push_back({{"t", c.t}, {"angular_velocity", v(c.angular_velocity)}});
        jb["angular_velocity_changes"] = ch;
      }
    }
    bodies.push_back(std::move(jb));
  }
  j["bodies"] = std::move(bodies);
  // Scenery only when present, so scenes without it and their digests stay as they were.
  const std::size_t mesh_triangles = s.scenery_mesh ? s.scenery_mesh->triangles.size() : 0;
  if (s.scenery.size() > mesh_triangles) {
    json sc = json::array();
    for (std::size_t i = 0; i + mesh_triangles < s.scenery.size(); ++i) {
      json poly = json::array();
      for (const Vec3& x : s.scenery[i].vertices) poly.push_back(v(x));
      sc.push_back({{"polygon", std::move(poly)}});
    }
    j["scenery"] = std::move(sc);
  }
  if (s.scenery_mesh) {
    json vs = json::array(), ts = json::array();
    for (const Vec3& x : s.scenery_mesh->vertices) vs.push_back(v(x));
    for (const auto& t : s.scenery_mesh->triangles) ts.push_back(json::array({t[0], t[1], t[2]}));
    j["scenery_mesh"] = {{"vertices", std::move(vs)}, {"triangles", std::move(ts)}};
  }
  return j;
}

void save_scene(const Scene& s, const std::string& path) {
  write_file_atomically(path, scene_to_json(s).dump(1) + "\n");
}

}  // namespace ccd
