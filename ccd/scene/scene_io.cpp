#include <ccd/scene/scene_io.hpp>

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/scene/scene_binary.hpp>

#include <string>

// Loading and writing scene files; reading the JSON is ccd/scene/scene_read.cpp, the
// invariants ccd/scene/scene_validate.cpp.
namespace ccd {
namespace {

using nlohmann::json;

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
