// ccdlab.rigid_toi: the contact times of two rigid bodies (shapes, poses and motions over a
// time span) with their certified errors, by the bracket search of the rigid ground truth
// (ccd/truth/rigid_truth.hpp, pair_bracket_events). The two bodies are read as a two-body
// ccdlab-scene/2 document, so every value is checked as in a scene file; the errors name
// the argument (`shape_a.half_extents`, `orientation_b`).
#include "bindings.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/rigid_truth.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace ccdlab::python {
namespace {

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;
const std::string kWho = "ccdlab.rigid_toi";

nlohmann::json numbers(const char* name, const Points& a, py::ssize_t n) {
  if (a.ndim() != 1 || a.shape(0) != n)
    throw ccd::InputError(kWho, name, "must be " + std::to_string(n) + " numbers");
  nlohmann::json out = nlohmann::json::array();
  for (py::ssize_t i = 0; i < n; ++i) {
    const double x = a.data()[i];
    if (!std::isfinite(x))
      throw ccd::InputError(kWho, std::string(name) + "[" + std::to_string(i) + "]", "must be finite");
    out.push_back(x);
  }
  return out;
}

/// A field of the two-body scene as the argument it came from: shapes[0].radius ->
/// shape_a.radius, bodies[1].orientation -> orientation_b, horizon -> duration.
std::string argument_of(const std::string& field) {
  for (int i = 0; i < 2; ++i) {
    const std::string side = i == 0 ? "_a" : "_b";
    const std::string shape = "shapes[" + std::to_string(i) + "]";
    const std::string body = "bodies[" + std::to_string(i) + "]";
    if (field.rfind(shape, 0) == 0) return "shape" + side + field.substr(shape.size());
    if (field.rfind(body + ".", 0) == 0) {
      const std::string rest = field.substr(body.size() + 1);
      const std::size_t cut = rest.find_first_of(".[");
      const std::string name = rest.substr(0, cut);
      return (name == "shape" ? "shape" : name) + side + (cut == std::string::npos ? "" : rest.substr(cut));
    }
    if (field == body) return "shape" + side;
  }
  return field == "horizon" ? "duration" : field;
}

struct Side {
  py::object shape;
  Points position, velocity;
  std::optional<Points> acceleration, orientation, angular_velocity;
};

nlohmann::json body_json(const Side& s, const char* name, const std::string& side) {
  const auto arg = [&](const char* what) { return std::string(what) + side; };
  nlohmann::json b = {{"shape", name},
                      {"position", numbers(arg("position").c_str(), s.position, 3)},
                      {"velocity", numbers(arg("velocity").c_str(), s.velocity, 3)}};
  if (s.acceleration) b["acceleration"] = numbers(arg("acceleration").c_str(), *s.acceleration, 3);
  if (s.orientation) b["orientation"] = numbers(arg("orientation").c_str(), *s.orientation, 4);
  if (s.angular_velocity) b["angular_velocity"] = numbers(arg("angular_velocity").c_str(), *s.angular_velocity, 3);
  return b;
}

nlohmann::json shape_json(const py::object& shape, const char* name, const std::string& side) {
  if (!py::isinstance<py::dict>(shape))
    throw ccd::InputError(kWho, "shape" + side,
                          "must be a dict as a scene's shapes entry: {\"kind\": \"box\", \"half_extents\": [...]}, "
                          "{\"kind\": \"sphere\", \"radius\": r}, capsule (half_length, radius) or hull (points)");
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, value] : shape.cast<py::dict>()) {  // each value named on its own
    const std::string field = "shape" + side + "." + py::str(key).cast<std::string>();
    try {
      j[py::str(key).cast<std::string>()] = from_python(value, kWho);
    } catch (const ccd::InputError& err) {
      throw ccd::InputError(kWho, field, std::string(err.what()).substr(err.file().size() + 2));
    }
  }
  j["name"] = name;
  return j;
}

/// The two-body scene, read and checked as a scene file; errors name the arguments.
ccd::Scene pair_scene(const Side& a, const Side& b, double duration) {
  nlohmann::json doc = {{"format", "ccdlab-scene/2"},
                        {"horizon", duration},
                        {"shapes", {shape_json(a.shape, "a", "_a"), shape_json(b.shape, "b", "_b")}},
                        {"bodies", {body_json(a, "a", "_a"), body_json(b, "b", "_b")}}};
  try {
    return ccd::scene_from_json(doc, kWho);
  } catch (const ccd::InputError& err) {
    const std::string prefix = err.file() + ": " + (err.field().empty() ? "" : err.field() + ": ");
    throw ccd::InputError(kWho, argument_of(err.field()), std::string(err.what()).substr(prefix.size()));
  }
}

py::dict rigid_toi(const Side& a, const Side& b, double duration, double time_tolerance,
                   std::size_t max_evaluations) {
  if (!(duration > 0.0 && std::isfinite(duration))) throw ccd::InputError(kWho, "duration", "must be finite and > 0");
  if (!(time_tolerance >= 0.0 && std::isfinite(time_tolerance)))
    throw ccd::InputError(kWho, "time_tolerance", "must be finite and >= 0 (0: 2^-30 x duration)");
  if (max_evaluations == 0) throw ccd::InputError(kWho, "max_evaluations", "must be > 0");
  const ccd::Scene scene = pair_scene(a, b, duration);
  // As the ground truth: 0 is 2^-30 x the horizon (ccd/truth/truth.cpp).
  const double tol = time_tolerance > 0.0 ? time_tolerance : std::ldexp(duration, -30);
  std::vector<ccd::ContactEvent> events;
  std::vector<ccd::EventError> errors;
  std::size_t evaluations = 0;
  {
    py::gil_scoped_release release;
    const ccd::Trajectories traj(scene);
    const ccd::RigidMotion motion(scene, traj);
    evaluations = ccd::pair_bracket_events(motion, 0, 1, 0.0, duration, tol, max_evaluations, events, errors);
  }
  py::list spans, details;
  for (std::size_t i = 0; i < events.size(); ++i) {
    spans.append(py::make_tuple(events[i].enter, events[i].exit));
    py::dict e;
    e["enter"] = events[i].enter;
    e["exit"] = events[i].exit;
    e["enter_error"] = errors[i].enter_error;
    e["exit_error"] = errors[i].exit_error;
    e["grazing"] = errors[i].grazing;
    e["undecided"] = errors[i].undecided;
    details.append(e);
  }
  py::dict d;
  const bool any = !events.empty();
  const bool grazing = any && errors[0].grazing;
  const bool at_start = any && !grazing && events[0].enter == 0.0 && errors[0].enter_error == 0.0;
  d["status"] = !any ? "miss" : grazing ? "grazing" : at_start ? "overlapping" : "hit";
  d["hit"] = any && !grazing;
  d["toi"] = any ? py::object(py::float_(events[0].enter)) : py::none();
  d["toi_error"] = any ? py::object(py::float_(errors[0].enter_error)) : py::none();
  d["intervals"] = spans;
  d["events"] = details;
  d["time_tolerance"] = tol;
  d["evaluations"] = evaluations;
  // Past max_evaluations the rest of the span is left unresolved (a wider bracket).
  d["complete"] = evaluations < max_evaluations;
  return d;
}

}  // namespace

void bind_rigid_queries(py::module_& m) {
  m.def(
      "rigid_toi",
      [](const py::object& shape_a, const Points& position_a, const Points& velocity_a, const py::object& shape_b,
         const Points& position_b, const Points& velocity_b, double duration, const std::optional<Points>& orientation_a,
         const std::optional<Points>& angular_velocity_a, const std::optional<Points>& acceleration_a,
         const std::optional<Points>& orientation_b, const std::optional<Points>& angular_velocity_b,
         const std::optional<Points>& acceleration_b, double time_tolerance, std::size_t max_evaluations) {
        const Side a{shape_a, position_a, velocity_a, acceleration_a, orientation_a, angular_velocity_a};
        const Side b{shape_b, position_b, velocity_b, acceleration_b, orientation_b, angular_velocity_b};
        return rigid_toi(a, b, duration, time_tolerance, max_evaluations);
      },
      py::arg("shape_a"), py::arg("position_a"), py::arg("velocity_a"), py::arg("shape_b"), py::arg("position_b"),
      py::arg("velocity_b"), py::arg("duration"), py::kw_only(), py::arg("orientation_a") = py::none(),
      py::arg("angular_velocity_a") = py::none(), py::arg("acceleration_a") = py::none(),
      py::arg("orientation_b") = py::none(), py::arg("angular_velocity_b") = py::none(),
      py::arg("acceleration_b") = py::none(), py::arg("time_tolerance") = 0.0, py::arg("max_evaluations") = 1000000,
      "Contact of two rigid bodies over s in [0, duration], certified as the rigid ground truth brackets it "
      "(docs/truth.md): shape_a, shape_b dicts as a scene's shapes entries ({\"kind\": \"box\", \"half_extents\": "
      "[hx, hy, hz]}, sphere (radius), capsule (half_length, radius), hull (points)); centres p + v s + a s^2/2; "
      "orientation a unit quaternion [w, x, y, z] (body to world) at s = 0, angular_velocity (rad/s, world "
      "frame) constant. Returns a dict: status (hit, overlapping, grazing: the closest approach stays within "
      "the tolerance band, contact undecided; miss), hit, toi (the first contact's enter, None on a miss), "
      "toi_error (the exact enter is within toi +- toi_error), intervals (enter, exit) and events (enter, exit, "
      "enter_error, exit_error, grazing, undecided), time_tolerance (0: 2^-30 x duration), evaluations, complete (False when max_evaluations ran out: "
      "what was left is one wide bracket)");
}

}  // namespace ccdlab::python
