#include "cloth_scene.hpp"

#include <ccd/io/json_reader.hpp>

#include <Eigen/Geometry>
#include <ccd/io/input_error.hpp>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <set>
#include <string_view>

namespace ccd::cloth {

namespace {

ClothScene base_sheet(int nx, int ny, double width, double depth) {
  ClothScene s;
  s.nx = nx;
  s.ny = ny;
  s.du = Vec3(width / (nx - 1), 0, 0);
  s.dv = Vec3(0, 0, depth / (ny - 1));
  s.particle_mass = 0.2 / (static_cast<double>(nx) * ny);  // a 0.2 kg sheet
  s.structural = {1000.0, 0.5};
  s.shear = {100.0, 0.05};
  s.bend = {5.0, 0.005};
  s.air_damping = 0.5 * s.particle_mass;  // a velocity time constant of 2 s
  s.thickness = 0.005;
  s.step = 0.005;
  return s;
}

}  // namespace

std::vector<std::string> builtin_cloth_scene_names() { return {"drape", "twist", "pile"}; }

ClothScene builtin_cloth_scene(const std::string& name, int n) {
  if (n < 4) throw std::invalid_argument("builtin_cloth_scene: n must be >= 4");
  if (name == "drape") {  // a 1 m sheet 0.15 m above a sphere of radius 0.25, floor below
    ClothScene s = base_sheet(n, n, 1.0, 1.0);
    s.origin = Vec3(-0.5, 0.4, -0.5);
    s.spheres.push_back({Vec3(0, 0, 0), 0.25});
    s.floor = -0.3;
    s.steps = 300;
    return s;
  }
  if (name == "twist") {  // a 1 m x 0.5 m sheet, end x = -0.5 held, end x = 0.5 turning at pi rad/s
    const int ny = std::max(4, n / 2);
    ClothScene s = base_sheet(n, ny, 1.0, 0.5);
    s.origin = Vec3(-0.5, 0, -0.25);
    Spin spin;
    spin.axis = Vec3::UnitX();
    spin.center = Vec3(0.5, 0, 0);
    spin.rate = std::numbers::pi;
    for (int j = 0; j < ny; ++j) {
      s.pinned.push_back(s.particle(0, j));
      spin.particles.push_back(s.particle(n - 1, j));
    }
    s.spin = spin;
    s.steps = 400;
    return s;
  }
  if (name == "pile") {  // a hanging 1 m sheet, slightly tilted, dropped onto the floor
    ClothScene s = base_sheet(n, n, 1.0, 1.0);
    s.origin = Vec3(-0.5, 0.05, 0);
    s.dv = Vec3(0, 1.0 / (n - 1), 0.05 / (n - 1));
    s.floor = 0.0;
    s.steps = 300;
    return s;
  }
  throw std::invalid_argument("builtin_cloth_scene: unknown scene '" + name + "'");
}

namespace {

using nlohmann::json;

const json& object(const JsonReader& r, const json& v, const std::string& field) {
  if (!v.is_object()) r.fail(field, "must be an object");
  return v;
}

double positive(const JsonReader& r, const json& v, const std::string& field) {
  const double x = r.number(v, field);
  if (!(x > 0)) r.fail(field, "must be > 0");
  return x;
}

double non_negative(const JsonReader& r, const json& v, const std::string& field) {
  const double x = r.number(v, field);
  if (!(x >= 0)) r.fail(field, "must be >= 0");
  return x;
}

SpringParams spring(const JsonReader& r, const json& obj, const std::string& path) {
  object(r, obj, path);
  r.only_fields(obj, path, {"stiffness", "damping"});
  return {non_negative(r, r.require(obj, "stiffness", path), path + ".stiffness"),
          non_negative(r, r.require(obj, "damping", path), path + ".damping")};
}

std::vector<std::uint32_t> particles(const JsonReader& r, const json& v, const std::string& field, std::size_t count) {
  if (!v.is_array()) r.fail(field, "must be an array of particle indices");
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    const auto p = static_cast<std::uint32_t>(r.integer(v[i], f, 0, static_cast<long long>(count) - 1));
    out.push_back(p);
  }
  return out;
}

ClothScene scene_from_json(const json& j, const std::string& file) {
  const JsonReader r{file};
  if (!j.is_object()) r.fail("", "a cloth scene must be a JSON object");
  r.only_fields(j, "", {"format", "grid", "particle_mass", "springs", "air_damping", "pinned", "spin", "gravity", "spheres", "floor",
                          "thickness", "step", "steps"});
  if (r.string(r.require(j, "format", ""), "format") != "ccdlab-cloth/1") r.fail("format", "must be \"ccdlab-cloth/1\"");
  ClothScene s;
  const json& g = object(r, r.require(j, "grid", ""), "grid");
  r.only_fields(g, "grid", {"nx", "ny", "origin", "du", "dv"});
  s.nx = static_cast<int>(r.integer(r.require(g, "nx", "grid"), "grid.nx", 2, 1000));
  s.ny = static_cast<int>(r.integer(r.require(g, "ny", "grid"), "grid.ny", 2, 1000));
  s.origin = r.vec3(r.require(g, "origin", "grid"), "grid.origin");
  s.du = r.vec3(r.require(g, "du", "grid"), "grid.du");
  s.dv = r.vec3(r.require(g, "dv", "grid"), "grid.dv");
  if (!(s.du.cross(s.dv).norm() > 0)) r.fail("grid.dv", "must not be parallel to grid.du (nor zero)");
  s.particle_mass = positive(r, r.require(j, "particle_mass", ""), "particle_mass");
  const json& sp = object(r, r.require(j, "springs", ""), "springs");
  r.only_fields(sp, "springs", {"structural", "shear", "bend"});
  s.structural = spring(r, r.require(sp, "structural", "springs"), "springs.structural");
  s.shear = spring(r, r.require(sp, "shear", "springs"), "springs.shear");
  s.bend = spring(r, r.require(sp, "bend", "springs"), "springs.bend");
  s.air_damping = r.optional_number(j, "air_damping", "", 0.0);
  if (!(s.air_damping >= 0)) r.fail("air_damping", "must be >= 0");
  const std::size_t count = s.particle_count();
  std::set<std::uint32_t> held;
  if (j.contains("pinned")) {
    s.pinned = particles(r, j["pinned"], "pinned", count);
    held.insert(s.pinned.begin(), s.pinned.end());
  }
  if (j.contains("spin")) {
    const json& o = object(r, j["spin"], "spin");
    r.only_fields(o, "spin", {"particles", "center", "axis", "rate"});
    Spin spin;
    spin.particles = particles(r, r.require(o, "particles", "spin"), "spin.particles", count);
    for (std::size_t i = 0; i < spin.particles.size(); ++i)
      if (held.count(spin.particles[i])) r.fail("spin.particles[" + std::to_string(i) + "]", "particle is also pinned");
    spin.center = r.vec3(r.require(o, "center", "spin"), "spin.center");
    spin.axis = r.vec3(r.require(o, "axis", "spin"), "spin.axis");
    if (!(spin.axis.norm() > 0)) r.fail("spin.axis", "must not be zero");
    spin.axis.normalize();
    spin.rate = r.number(r.require(o, "rate", "spin"), "spin.rate");
    s.spin = spin;
  }
  s.gravity = r.optional_vec3(j, "gravity", "");
  if (j.contains("spheres")) {
    const json& a = j["spheres"];
    if (!a.is_array()) r.fail("spheres", "must be an array");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = "spheres[" + std::to_string(i) + "]";
      object(r, a[i], p);
      r.only_fields(a[i], p, {"center", "radius"});
      s.spheres.push_back({r.vec3(r.require(a[i], "center", p), p + ".center"), positive(r, r.require(a[i], "radius", p), p + ".radius")});
    }
  }
  if (j.contains("floor")) s.floor = r.number(j["floor"], "floor");
  s.thickness = non_negative(r, r.require(j, "thickness", ""), "thickness");
  s.step = positive(r, r.require(j, "step", ""), "step");
  s.steps = static_cast<int>(r.integer(r.require(j, "steps", ""), "steps", 1, 1000000));
  return s;
}

}  // namespace

ClothScene parse_cloth_scene(const std::string& text, const std::string& file) {
  return scene_from_json(parse_json_text(text, file), file);
}

ClothScene read_cloth_scene(const std::string& path) { return scene_from_json(read_json_file(path), path); }

}  // namespace ccd::cloth
