#include <ccd/scene/scene_io.hpp>

#include <ccd/io/input_error.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/scene/scene_field_paths.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

// Reading a scene from its JSON (scene_from_json): every field read and type-checked here,
// naming the field path on failure; the scene's invariants are then checked by
// validate_scene (ccd/scene/scene_validate.cpp).
namespace ccd {
namespace {

using nlohmann::json;
using Reader = JsonReader;
using ShapeIndex = std::unordered_map<std::string, std::size_t>;  // name -> index

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
  for (std::size_t k = 0; k < 3; ++k)
    out[k] = boundary_name(r, v[k], "box.boundary[" + std::to_string(k) + "]");
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
    case ShapeKind::Sphere:
      r.only_fields(o, p, {"name", "kind", "radius"});
      break;
    case ShapeKind::Capsule:
      r.only_fields(o, p, {"name", "kind", "half_length", "radius"});
      break;
    case ShapeKind::Box:
      r.only_fields(o, p, {"name", "kind", "half_extents"});
      break;
    case ShapeKind::Hull:
      r.only_fields(o, p, {"name", "kind", "points"});
      break;
  }
  switch (s.kind) {
    case ShapeKind::Sphere:
      s.radius = r.number(r.require(o, "radius", p), p + ".radius");
      break;
    case ShapeKind::Capsule:
      s.half_length = r.number(r.require(o, "half_length", p), p + ".half_length");
      s.radius = r.number(r.require(o, "radius", p), p + ".radius");
      break;
    case ShapeKind::Box:
      s.half_extents = r.vec3(r.require(o, "half_extents", p), p + ".half_extents");
      break;
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

// "box": min, max and boundary.
WallBox box_from_json(const Reader& r, const json& o) {
  if (!o.is_object()) r.fail("box", "must be an object with min and max");
  r.only_fields(o, "box", {"min", "max", "boundary"});
  WallBox box;
  box.min = r.vec3(r.require(o, "min", "box"), "box.min");
  box.max = r.vec3(r.require(o, "max", "box"), "box.max");
  if (auto b = o.find("boundary"); b != o.end()) box.boundary = boundary_from_json(r, *b);
  return box;
}

// "shapes": each shape, names unique.
void read_shapes(const Reader& r, const json& a, Scene& s, ShapeIndex& shape_index) {
  if (!a.is_array()) r.fail("shapes", "must be an array");
  for (std::size_t i = 0; i < a.size(); ++i) {
    Shape sh = shape_from_json(r, a[i], shape_path(i));
    const auto [at, added] = shape_index.emplace(sh.name, i);
    if (!added)
      r.fail(shape_path(i) + ".name", "\"" + sh.name + "\" is already the name of " + shape_path(at->second));
    s.shapes.push_back(std::move(sh));
  }
}

// A body's list of timed changes (`key`: acceleration_changes, velocity_changes,
// angular_velocity_changes), each {"t": ..., `value`: [x, y, z]}; `set` stores the vector.
template <class Change, class Set>
void read_changes(const Reader& r, const json& b, const char* key, const std::string& p, const char* value,
                  std::vector<Change>& out, Set set) {
  const auto it = b.find(key);
  if (it == b.end()) return;
  const std::string cp = p + "." + key;
  if (!it->is_array()) r.fail(cp, "must be an array");
  for (std::size_t k = 0; k < it->size(); ++k) {
    const json& c = (*it)[k];
    const std::string kp = cp + "[" + std::to_string(k) + "]";
    if (!c.is_object()) r.fail(kp, std::string("must be an object with t and ") + value);
    r.only_fields(c, kp, {"t", value});
    Change ch;
    ch.t = r.number(r.require(c, "t", kp), kp + ".t");
    set(ch, r.vec3(r.require(c, value, kp), kp + "." + value));
    out.push_back(ch);
  }
}

// A body's orientation: a unit quaternion [w, x, y, z] (normalised when within the
// tolerance and not already normalised).
Eigen::Quaterniond orientation_from_json(const Reader& r, const json& v, const std::string& op) {
  if (!v.is_array() || v.size() != 4) r.fail(op, "must be a quaternion [w, x, y, z]");
  double q[4];
  for (std::size_t k = 0; k < 4; ++k) q[k] = r.number(v[k], op + "[" + std::to_string(k) + "]");
  Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
  const double n = quat.norm();
  if (!(std::fabs(n - 1.0) <= kQuaternionTolerance))
    r.fail(op, "must be a unit quaternion (|q| is " + std::to_string(n) + ")");
  if (!(std::fabs(quat.squaredNorm() - 1.0) <= kNormalisedTolerance)) quat.normalize();
  return quat;
}

// A body's version-2 fields after its shape: orientation, spin and mass properties.
void read_spin(const Reader& r, const json& b, const std::string& p, RigidBody& rigid) {
  if (auto it = b.find("orientation"); it != b.end())
    rigid.orientation = orientation_from_json(r, *it, p + ".orientation");
  rigid.angular_velocity = r.optional_vec3(b, "angular_velocity", p);
  read_changes(r, b, "angular_velocity_changes", p, "angular_velocity", rigid.angular_velocity_changes,
               [](AngularVelocityChange& c, const Vec3& x) { c.angular_velocity = x; });
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
}

// "bodies[i]": appends the body (and its shape and spin entry in a version-2 scene).
void read_body(const Reader& r, const json& b, std::size_t i, bool v2, const ShapeIndex& shape_index,
               Scene& s) {
  const std::string p = body_path(i);
  if (!b.is_object()) r.fail(p, "must be an object");
  r.only_fields(
      b, p,
      {"radius", "position", "velocity", "acceleration", "acceleration_changes", "velocity_changes", "shape",
       "orientation", "angular_velocity", "angular_velocity_changes", "spin", "mass", "density", "inertia"});
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
  read_changes(r, b, "acceleration_changes", p, "acceleration", body.acceleration_changes,
               [](AccelerationChange& c, const Vec3& x) { c.acceleration = x; });
  read_changes(r, b, "velocity_changes", p, "velocity", body.velocity_changes,
               [](VelocityChange& c, const Vec3& x) { c.velocity = x; });
  for (const char* key :
       {"orientation", "angular_velocity", "angular_velocity_changes", "spin", "mass", "density", "inertia"})
    if (!v2 && b.contains(key)) r.fail(p + "." + key, "needs format \"ccdlab-scene/2\"");
  read_spin(r, b, p, rigid);
  if (rigid.shape != kNoShape)
    body.radius = s.shapes[static_cast<std::size_t>(rigid.shape)].enclosing_radius();
  s.bodies.push_back(std::move(body));
  if (v2) s.rigid.push_back(std::move(rigid));
}

// "scenery": polygons.
void read_scenery(const Reader& r, const json& a, Scene& s) {
  if (!a.is_array()) r.fail("scenery", "must be an array of {\"polygon\": [[x, y, z], ...]}");
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string p = "scenery[" + std::to_string(i) + "]";
    const json& o = a[i];
    if (!o.is_object()) r.fail(p, "must be an object {\"polygon\": [[x, y, z], ...]}");
    r.only_fields(o, p, {"polygon"});
    const json& poly = r.require(o, "polygon", p);
    if (!poly.is_array()) r.fail(p + ".polygon", "must be an array of [x, y, z] vertices");
    std::vector<Vec3> vs;
    for (std::size_t k = 0; k < poly.size(); ++k)
      vs.push_back(r.vec3(poly[k], p + ".polygon[" + std::to_string(k) + "]"));
    s.scenery.push_back(polygon_from_vertices(std::move(vs)));
  }
}

// "scenery_mesh": vertices and triangles; each triangle is also a scenery polygon.
void read_scenery_mesh(const Reader& r, const json& o, Scene& s) {
  if (!o.is_object()) r.fail("scenery_mesh", "must be an object with vertices and triangles");
  r.only_fields(o, "scenery_mesh", {"vertices", "triangles"});
  SceneryMesh mesh;
  const json& vs = r.require(o, "vertices", "scenery_mesh");
  if (!vs.is_array()) r.fail("scenery_mesh.vertices", "must be an array of [x, y, z]");
  for (std::size_t k = 0; k < vs.size(); ++k)
    mesh.vertices.push_back(r.vec3(vs[k], "scenery_mesh.vertices[" + std::to_string(k) + "]"));
  const json& ts = r.require(o, "triangles", "scenery_mesh");
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

}  // namespace

Scene scene_from_json(const json& j, const std::string& file) {
  Reader r{file};
  if (!j.is_object()) r.fail("", "a scene must be a JSON object");
  // Version-2 names are known in both versions: a version-1 file that uses one is told
  // it needs version 2 (below), not that the field is unknown.
  r.only_fields(j, "",
                {"format", "horizon", "gravity", "box", "shapes", "bodies", "scenery", "scenery_mesh"});
  const json& format = r.require(j, "format", "");
  if (!format.is_string() ||
      (format.get<std::string>() != kSceneFormatV1 && format.get<std::string>() != kSceneFormat))
    r.fail("format", "must be \"ccdlab-scene/1\" or \"ccdlab-scene/2\"");
  const bool v2 = format.get<std::string>() == kSceneFormat;
  auto version_2 = [&](const char* key) {
    if (!v2) r.fail(key, "needs format \"ccdlab-scene/2\"");
  };
  Scene s;
  s.horizon = r.number(r.require(j, "horizon", ""), "horizon");
  s.gravity = r.optional_vec3(j, "gravity", "");
  if (auto it = j.find("box"); it != j.end() && !it->is_null()) s.box = box_from_json(r, *it);
  ShapeIndex shape_index;
  if (auto it = j.find("shapes"); it != j.end()) {
    version_2("shapes");
    read_shapes(r, *it, s, shape_index);
  }
  const json& bodies = r.require(j, "bodies", "");
  if (!bodies.is_array()) r.fail("bodies", "must be an array");
  s.bodies.reserve(bodies.size());
  if (v2) s.rigid.reserve(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) read_body(r, bodies[i], i, v2, shape_index, s);
  // Static scenery (docs/scenery.md): polygons, then the mesh's triangles.
  if (auto it = j.find("scenery"); it != j.end()) {
    version_2("scenery");
    read_scenery(r, *it, s);
  }
  if (auto it = j.find("scenery_mesh"); it != j.end()) {
    version_2("scenery_mesh");
    read_scenery_mesh(r, *it, s);
  }
  // A version-2 file of plain spheres without spin is a sphere scene: no side table.
  if (std::none_of(s.rigid.begin(), s.rigid.end(),
                   [](const RigidBody& x) { return x.shape != kNoShape || x.spins(); }))
    s.rigid.clear();
  validate_scene(s, file);
  return s;
}

}  // namespace ccd
