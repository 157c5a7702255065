#include <ccd/scene/scene_io.hpp>

#include <ccd/io/atomic_file.hpp>
#include <ccd/geometry/double_double.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/scene/input_error.hpp>

#include <cmath>
#include <cstdio>

namespace ccd {
namespace {

using nlohmann::json;

using Reader = JsonReader;

std::string body_path(std::size_t i) { return "bodies[" + std::to_string(i) + "]"; }

}  // namespace

Scene scene_from_json(const json& j, const std::string& file) {
  Reader r{file};
  if (!j.is_object()) r.fail("", "a scene must be a JSON object");
  r.only_fields(j, "", {"format", "horizon", "gravity", "box", "bodies"});
  const json& format = r.require(j, "format", "");
  if (!format.is_string() || format.get<std::string>() != "ccdlab-scene/1")
    r.fail("format", "must be \"ccdlab-scene/1\"");
  Scene s;
  s.horizon = r.number(r.require(j, "horizon", ""), "horizon");
  s.gravity = r.optional_vec3(j, "gravity", "");
  if (auto it = j.find("box"); it != j.end() && !it->is_null()) {
    if (!it->is_object()) r.fail("box", "must be an object with min and max");
    r.only_fields(*it, "box", {"min", "max"});
    WallBox box;
    box.min = r.vec3(r.require(*it, "min", "box"), "box.min");
    box.max = r.vec3(r.require(*it, "max", "box"), "box.max");
    s.box = box;
  }
  const json& bodies = r.require(j, "bodies", "");
  if (!bodies.is_array()) r.fail("bodies", "must be an array");
  s.bodies.reserve(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const json& b = bodies[i];
    const std::string p = body_path(i);
    if (!b.is_object()) r.fail(p, "must be an object");
    r.only_fields(b, p, {"radius", "position", "velocity", "acceleration", "acceleration_changes"});
    Body body;
    body.radius = r.number(r.require(b, "radius", p), p + ".radius");
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
    s.bodies.push_back(std::move(body));
  }
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
  finite3(s.gravity, "gravity");
  if (s.box) {
    finite3(s.box->min, "box.min");
    finite3(s.box->max, "box.max");
    for (int a = 0; a < 3; ++a)
      if (!(s.box->min[a] < s.box->max[a]))
        r.fail("box", "min must be < max on every axis (axis " + std::to_string(a) + ")");
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
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    const std::string p = body_path(i);
    magnitude(b.radius, p + ".radius");
    if (b.radius <= 0.0) r.fail(p + ".radius", "must be > 0");
    finite3(b.position, p + ".position");
    finite3(b.velocity, p + ".velocity");
    finite3(b.acceleration, p + ".acceleration");
    reach(b.velocity.norm() * T, p + ".velocity", "|velocity| * horizon");
    reach((b.acceleration + s.gravity).norm() * (0.5 * T * T), p + ".acceleration",
          "|acceleration + gravity| * horizon^2 / 2");
    if (s.box) {
      for (int a = 0; a < 3; ++a) {
        if (b.position[a] - b.radius < s.box->min[a] || b.position[a] + b.radius > s.box->max[a])
          r.fail(p + ".position", "body must start inside the box (centre at least radius from every wall)");
        // A body as wide as the box on an axis touches both walls at once: it cannot move
        // along that axis (it would reflect at both walls in zero time and leave the box).
        // Wall planes as the trajectory takes them: the exact sums, compared exactly.
        const Dd room = two_sum(s.box->max[a], -b.radius) - two_sum(s.box->min[a], b.radius);
        if (!(room.value() > 0.0) && b.velocity[a] != 0.0)
          r.fail(p + ".velocity[" + std::to_string(a) + "]",
                 "must be 0: the body fills the box on this axis (no room to move between the walls)");
      }
    }
    double prev = 0.0;
    for (std::size_t k = 0; k < b.acceleration_changes.size(); ++k) {
      const AccelerationChange& c = b.acceleration_changes[k];
      const std::string kp = p + ".acceleration_changes[" + std::to_string(k) + "]";
      if (!std::isfinite(c.t) || c.t <= prev || c.t >= s.horizon)
        r.fail(kp + ".t", "must increase strictly and lie in (0, horizon)");
      finite3(c.acceleration, kp + ".acceleration");
      reach((c.acceleration + s.gravity).norm() * (0.5 * T * T), kp + ".acceleration",
            "|acceleration + gravity| * horizon^2 / 2");
      prev = c.t;
    }
  }
}

Scene load_scene(const std::string& path) { return scene_from_json(read_json_file(path), path); }

json scene_to_json(const Scene& s) {
  auto v = [](const Vec3& x) { return json::array({x.x(), x.y(), x.z()}); };
  json j;
  j["format"] = "ccdlab-scene/1";
  j["horizon"] = s.horizon;
  j["gravity"] = v(s.gravity);
  if (s.box) j["box"] = {{"min", v(s.box->min)}, {"max", v(s.box->max)}};
  json bodies = json::array();
  for (const Body& b : s.bodies) {
    json jb = {{"radius", b.radius}, {"position", v(b.position)}, {"velocity", v(b.velocity)},
               {"acceleration", v(b.acceleration)}};
    if (!b.acceleration_changes.empty()) {
      json ch = json::array();
      for (const AccelerationChange& c : b.acceleration_changes)
        ch.push_back({{"t", c.t}, {"acceleration", v(c.acceleration)}});
      jb["acceleration_changes"] = ch;
    }
    bodies.push_back(std::move(jb));
  }
  j["bodies"] = std::move(bodies);
  return j;
}

void save_scene(const Scene& s, const std::string& path) {
  write_file_atomically(path, scene_to_json(s).dump(1) + "\n");
}

}  // namespace ccd
