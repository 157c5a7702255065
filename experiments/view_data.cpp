#include "view_data.hpp"

#include "results_file.hpp"
#include "view_volumes.hpp"
#include "work_estimate.hpp"

#include <ccd/io/utf8_text.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/motion/rotation.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/shape/shape_kind.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <sys/resource.h>

namespace ccdlab {
namespace {

using nlohmann::json;

double shown(double x) { return view_number(x); }

void append(json& out, const ccd::Vec3& v) {
  for (int k = 0; k < 3; ++k) out.push_back(shown(v[k]));
}

json vec(const ccd::Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

// The sampled poses of a free tumble: at most 0.05 rad apart, 1 to 100000 per piece.
int tumble_samples(const ccd::RotationPiece& q) {
  const double turn = q.max_rate() * (q.t1 - q.t0);
  return static_cast<int>(std::clamp(std::ceil(turn / 0.05), 1.0, 100000.0));
}

// Refuses, before any of it is built, a page of more than kMaxViewEntries entries (one per
// trajectory piece and per rotation piece or sampled pose) unless forced.
void check_page_size(const ccd::Scene& scene, const ccd::Trajectories& traj, const ccd::Rotations& rot,
                     const ViewInputs& in) {
  double entries = static_cast<double>(traj.total_pieces() + scene.scenery.size()), tumbles = 0.0;
  if (!rot.empty())
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
      for (const ccd::RotationPiece& q : rot.pieces(i)) {
        const double k = q.constant_spin() ? 1.0 : tumble_samples(q);
        entries += k;
        if (!q.constant_spin()) tumbles += k;
      }
  check_work({entries, kMaxViewEntries, "page entries",
              std::to_string(scene.bodies.size()) + " bodies, " + std::to_string(traj.total_pieces()) +
                  " trajectory pieces, " + work_number(tumbles) + " sampled poses of free spins"},
             in.force, in.scene_file, "bodies");
  // Under an address-space limit (ulimit -v), a page that cannot fit is out of memory now,
  // not after minutes of building: about 400 bytes an entry as JSON values and as text.
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      entries * 400.0 > static_cast<double>(limit.rlim_cur))
    throw std::bad_alloc();
}

// A record's body-scenery misses (static_missed_events), checked against the scene's body
// and polygon counts and horizon, as the page shows them: {body, polygon, enter, exit}.
json static_missed_of(const json& m, const ccd::JsonReader& r, const std::string& at, std::size_t bodies,
                      std::size_t polygons, double horizon) {
  if (!m.is_array()) r.fail(at, "must be an array");
  json missed = json::array();
  for (std::size_t k = 0; k < m.size(); ++k) {
    const json& e = m[k];
    const std::string f = at + "[" + std::to_string(k) + "]";
    if (!e.is_object()) r.fail(f, "must be an object {body, polygon, enter, exit}");
    const std::uint32_t body = r.index(r.require(e, "body", f), f + ".body");
    const std::uint32_t polygon = r.index(r.require(e, "polygon", f), f + ".polygon");
    const double enter = r.number(r.require(e, "enter", f), f + ".enter");
    const double exit = r.number(r.require(e, "exit", f), f + ".exit");
    if (body >= bodies) r.fail(f + ".body", "must be a body of the scene (it has " + std::to_string(bodies) + ")");
    if (polygon >= polygons)
      r.fail(f + ".polygon", "must be a scenery polygon of the scene (it has " + std::to_string(polygons) + ")");
    if (!(0.0 <= enter && enter <= exit && exit <= horizon))
      r.fail(f + ".exit", "must satisfy 0 <= enter <= exit <= horizon");
    missed.push_back({{"body", body}, {"polygon", polygon}, {"enter", enter}, {"exit", exit}});
  }
  return missed;
}

// The records of a results file, with what the page shows of each (its missed contacts
// checked against the scene's body and scenery polygon counts and horizon).
json runs_of(const json& results, const std::string& file, std::size_t bodies, std::size_t polygons,
             double horizon) {
  const ccd::JsonReader r{file};
  json runs = json::array();
  const double accel = results["experiment"]["acceleration_bound_used"].get<double>();
  const json& records = results["records"];
  for (std::size_t i = 0; i < records.size(); ++i) {
    const json& rec = records[i];
    const std::string at = "records[" + std::to_string(i) + "]";
    json run;
    for (const char* k : {"method", "bound", "broad_phase", "options", "knowledge", "continuous", "conservative", "dt",
                          "hz", "steps", "events", "initial_contacts", "detected", "missed", "candidates",
                          "bound_candidates", "false_positives", "total_seconds", "undecided", "static_events",
                          "static_initial_contacts", "static_undecided", "static_detected", "static_missed"})
      if (rec.contains(k)) run[k] = rec[k];
    run["acceleration_bound"] = accel;
    if (auto m = rec.find("missed_events"); m != rec.end()) {
      if (!m->is_array()) r.fail(at + ".missed_events", "must be an array");
      json missed = json::array();
      for (std::size_t k = 0; k < m->size(); ++k) {
        const json& e = (*m)[k];
        const std::string f = at + ".missed_events[" + std::to_string(k) + "]";
        if (!e.is_object()) r.fail(f, "must be an object {a, b, enter, exit}");
        const std::uint32_t a = r.index(r.require(e, "a", f), f + ".a");
        const std::uint32_t b = r.index(r.require(e, "b", f), f + ".b");
        const double enter = r.number(r.require(e, "enter", f), f + ".enter");
        const double exit = r.number(r.require(e, "exit", f), f + ".exit");
        if (a >= b) r.fail(f + ".b", "must be greater than a");
        if (b >= bodies) r.fail(f + ".b", "must be a body of the scene (it has " + std::to_string(bodies) + ")");
        if (!(0.0 <= enter && enter <= exit && exit <= horizon))
          r.fail(f + ".exit", "must satisfy 0 <= enter <= exit <= horizon");
        missed.push_back({{"a", a}, {"b", b}, {"enter", enter}, {"exit", exit}});
      }
      run["missed_events"] = std::move(missed);
    }
    if (auto m = rec.find("static_missed_events"); m != rec.end())
      run["static_missed_events"] = static_missed_of(*m, r, at + ".static_missed_events", bodies, polygons, horizon);
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace

double view_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return std::strtod(text, nullptr);
}

json body_view_data(const ccd::Scene& scene, const ViewInputs& in) {
  const std::string digest = ccd::scene_digest(scene);
  if (in.results) {
    validate_results(*in.results, in.results_file);
    if ((*in.results)["truth"]["scene_sha256"].get<std::string>() != digest)
      throw ccd::InputError(in.results_file, "truth.scene_sha256",
                            "these are the results of another scene than " + in.scene_file);
  }
  if (in.truth && !in.truth->scene_sha256.empty() && in.truth->scene_sha256 != digest)
    throw ccd::InputError(in.truth_file, "scene_sha256", "this is the ground truth of another scene than " + in.scene_file);
  if (in.truth && in.truth->horizon != scene.horizon)
    throw ccd::InputError(in.truth_file, "horizon", "differs from the scene's horizon");
  const std::size_t n = scene.bodies.size();
  if (in.truth)
    for (std::size_t i = 0; i < in.truth->events.size(); ++i)
      if (in.truth->events[i].b >= n)
        throw ccd::InputError(in.truth_file, "events[" + std::to_string(i) + "].b", "is not a body of the scene");

  const ccd::Trajectories traj(scene);
  const ccd::Rotations rot(scene);
  check_page_size(scene, traj, rot, in);
  json data;
  data["format"] = kViewDataFormat;
  data["kind"] = "bodies";
  data["scene_file"] = ccd::escape_invalid_utf8(in.scene_file);
  data["horizon"] = scene.horizon;
  data["gravity"] = vec(scene.gravity);
  data["max_acceleration"] = scene.max_acceleration();
  data["box"] = scene.box ? json{{"min", vec(scene.box->min)}, {"max", vec(scene.box->max)}} : json(nullptr);
  json shapes = json::array();
  for (const ccd::Shape& s : scene.shapes) {
    json j{{"name", s.name}, {"kind", std::string(ccd::to_string(s.kind))}};
    if (s.kind == ccd::ShapeKind::Sphere || s.kind == ccd::ShapeKind::Capsule) j["radius"] = s.radius;
    if (s.kind == ccd::ShapeKind::Capsule) j["half_length"] = s.half_length;
    if (s.kind == ccd::ShapeKind::Box) j["half_extents"] = vec(s.half_extents);
    if (s.kind == ccd::ShapeKind::Hull) {
      j["points"] = json::array();
      for (const ccd::Vec3& p : s.points) j["points"].push_back(vec(p));
    }
    shapes.push_back(std::move(j));
  }
  data["shapes"] = std::move(shapes);
  // The static scenery (polygons, then the triangles of scenery_mesh): each polygon's
  // vertices, flat [x0, y0, z0, x1, ...].
  json scenery = json::array();
  for (const ccd::StaticPolygon& poly : scene.scenery) {
    json flat = json::array();
    for (const ccd::Vec3& v : poly.vertices) append(flat, v);
    scenery.push_back(std::move(flat));
  }
  data["scenery"] = std::move(scenery);

  // Per body: radius, shape index (-1: a plain sphere), centre pieces
  // [t0, t1, p, v, a] and, for spinning shapes, rotation pieces [t0, t1, q (w x y z), omega].
  json radius = json::array(), shape = json::array(), pieces = json::array(), rotations = json::array();
  for (std::size_t i = 0; i < n; ++i) {
    radius.push_back(shown(scene.bodies[i].radius));
    shape.push_back(scene.rigid.empty() ? -1 : scene.rigid[i].shape);
    json flat = json::array();
    for (const ccd::Piece& q : traj.pieces(i)) {
      flat.push_back(shown(q.t0));
      flat.push_back(shown(q.t1));
      append(flat, q.p);
      append(flat, q.v);
      append(flat, q.a);
    }
    pieces.push_back(std::move(flat));
    if (!rot.empty()) {
      json r = json::array();
      for (const ccd::RotationPiece& q : rot.pieces(i)) {
        if (q.constant_spin()) {
          for (double x : {q.t0, q.t1, q.q0.w(), q.q0.x(), q.q0.y(), q.q0.z()}) r.push_back(shown(x));
          append(r, q.omega);
          continue;
        }
        // A free tumble: sampled poses (at most 0.05 rad apart), each pair joined by the
        // constant spin that turns one into the next.
        const int steps = tumble_samples(q);
        ccd::Quat a = q.orientation(q.t0);
        for (int k = 0; k < steps; ++k) {
          const double s0 = q.t0 + (q.t1 - q.t0) * k / steps, s1 = k + 1 == steps ? q.t1 : q.t0 + (q.t1 - q.t0) * (k + 1) / steps;
          const ccd::Quat b = q.orientation(s1);
          ccd::Quat d = b * a.conjugate();
          if (d.w() < 0.0) d.coeffs() = -d.coeffs();  // the short way round
          const Eigen::AngleAxisd step(d);
          const ccd::Vec3 omega = s1 > s0 ? ccd::Vec3(step.axis() * (step.angle() / (s1 - s0))) : ccd::Vec3::Zero();
          for (double x : {s0, s1, a.w(), a.x(), a.y(), a.z()}) r.push_back(shown(x));
          append(r, omega);
          a = b;
        }
      }
      rotations.push_back(std::move(r));
    }
  }
  data["bodies"] = {{"count", n}, {"radius", std::move(radius)}, {"shape", std::move(shape)},
                    {"pieces", std::move(pieces)}, {"rotations", std::move(rotations)}};

  data["truth_file"] = in.truth ? json(ccd::escape_invalid_utf8(in.truth_file)) : json(nullptr);
  data["truth"] = json(nullptr);
  data["static_truth"] = json(nullptr);
  if (in.truth) {
    json events = json::array();
    for (const ccd::ContactEvent& e : in.truth->events)
      events.push_back(json::array({e.a, e.b, e.enter, e.exit}));
    data["truth"] = std::move(events);
    // Body-scenery contacts: [body, polygon, enter, exit].
    json statics = json::array();
    for (std::size_t i = 0; i < in.truth->static_events.size(); ++i) {
      const ccd::StaticEvent& e = in.truth->static_events[i];
      if (e.body >= n || e.polygon >= scene.scenery.size())
        throw ccd::InputError(in.truth_file, "static_events[" + std::to_string(i) + "]",
                              "is not a body and scenery polygon of the scene");
      statics.push_back(json::array({e.body, e.polygon, e.enter, e.exit}));
    }
    data["static_truth"] = std::move(statics);
  }
  data["results_file"] = in.results ? json(ccd::escape_invalid_utf8(in.results_file)) : json(nullptr);
  data["runs"] = in.results ? runs_of(*in.results, in.results_file, n, scene.scenery.size(), scene.horizon)
                            : json::array();
  add_run_volumes(scene, traj, data["runs"]);
  return data;
}

json cloth_view_data(const json& j, const std::string& file, bool force) {
  const ccd::JsonReader r{file};
  if (!j.is_object()) r.fail("", "must be a JSON object");
  const std::string format = r.string(r.require(j, "format", ""), "format");
  if (format != "ccdlab-cloth-frames/1") r.fail("format", "must be \"ccdlab-cloth-frames/1\"");
  const long long nx = r.integer(r.require(j, "nx", ""), "nx", 2, 1000);
  const long long ny = r.integer(r.require(j, "ny", ""), "ny", 2, 1000);
  const std::size_t particles = static_cast<std::size_t>(nx * ny);
  json data;
  data["format"] = kViewDataFormat;
  data["kind"] = "cloth";
  data["scene_file"] = ccd::escape_invalid_utf8(file);
  data["nx"] = nx;
  data["ny"] = ny;
  const json& tris = r.require(j, "triangles", "");
  if (!tris.is_array()) r.fail("triangles", "must be an array");
  json triangles = json::array();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const std::string f = "triangles[" + std::to_string(i) + "]";
    if (!tris[i].is_array() || tris[i].size() != 3) r.fail(f, "must be 3 particle indices");
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t v = r.index(tris[i][k], f + "[" + std::to_string(k) + "]");
      if (v >= particles) r.fail(f + "[" + std::to_string(k) + "]", "must be below nx * ny = " + std::to_string(particles));
      triangles.push_back(v);
    }
  }
  data["triangles"] = std::move(triangles);
  json spheres = json::array();
  if (auto s = j.find("spheres"); s != j.end()) {
    if (!s->is_array()) r.fail("spheres", "must be an array");
    for (std::size_t i = 0; i < s->size(); ++i) {
      const std::string f = "spheres[" + std::to_string(i) + "]";
      const double radius = r.number(r.require((*s)[i], "radius", f), f + ".radius");
      if (!(radius > 0.0)) r.fail(f + ".radius", "must be > 0");
      spheres.push_back({{"center", vec(r.vec3(r.require((*s)[i], "center", f), f + ".center"))}, {"radius", radius}});
    }
  }
  data["spheres"] = std::move(spheres);
  data["floor"] = nullptr;
  if (auto fl = j.find("floor"); fl != j.end() && !fl->is_null()) data["floor"] = r.number(*fl, "floor");
  const json& fr = r.require(j, "frames", "");
  if (!fr.is_array() || fr.empty()) r.fail("frames", "must be a non-empty array");
  check_work({static_cast<double>(fr.size()) * static_cast<double>(particles), kMaxViewEntries, "page entries",
              std::to_string(fr.size()) + " frames of " + std::to_string(nx) + " x " + std::to_string(ny) +
                  " particles"},
             force, file, "frames");
  json frames = json::array();
  double last = -1.0;
  for (std::size_t i = 0; i < fr.size(); ++i) {
    const std::string f = "frames[" + std::to_string(i) + "]";
    const double t = r.number(r.require(fr[i], "t", f), f + ".t");
    if (!(t > last)) r.fail(f + ".t", i == 0 ? "must be >= 0" : "must be later than the frame before");
    last = t;
    const json& x = r.require(fr[i], "x", f);
    if (!x.is_array() || x.size() != 3 * particles)
      r.fail(f + ".x", "must hold 3 nx ny = " + std::to_string(3 * particles) + " coordinates");
    json xs = json::array();
    for (std::size_t k = 0; k < x.size(); ++k) xs.push_back(shown(r.number(x[k], f + ".x[" + std::to_string(k) + "]")));
    frames.push_back({{"t", t}, {"x", std::move(xs)}});
  }
  data["horizon"] = last;
  data["frames"] = std::move(frames);
  return data;
}

}  // namespace ccdlab
