#include <ccd/scene/recorded_frames.hpp>

#include <ccd/geometry/double_double.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

namespace ccd {
namespace {

// Largest accepted | |q| - 1 | of a recorded orientation (the scene format's own).
constexpr double kQuaternionTolerance = 1e-6;

enum Column : int { kBody, kT, kX, kY, kZ, kRadius, kShape, kQw, kQx, kQy, kQz, kColumns };
constexpr std::array<std::string_view, kColumns> kNames = {"body",  "t",  "x",  "y",  "z", "radius",
                                                           "shape", "qw", "qx", "qy", "qz"};

struct Frame {
  double t = 0.0;
  Vec3 p{Vec3::Zero()};
  Eigen::Quaterniond q{Eigen::Quaterniond::Identity()};
  std::size_t line = 0;
};

struct Track {
  std::vector<Frame> frames;
  std::optional<double> radius;
  std::string shape;          // empty: a plain sphere
  std::size_t size_line = 0;  // the line that fixed radius or shape
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Cells of one CSV line, trimmed; a cell in double quotes may hold commas ("" is a
// quote), as Python's csv module writes `"box:1,0.5,0.25"`. nullopt: an unclosed quote.
std::optional<std::vector<std::string>> split(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) return std::nullopt;
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell += line[i++];
      }
      const std::size_t comma = line.find(',', i);
      if (!trim(line.substr(i, comma == std::string_view::npos ? std::string_view::npos : comma - i)).empty())
        return std::nullopt;  // text after the closing quote
      cells.push_back(std::move(cell));
      if (comma == std::string_view::npos) break;
      i = comma + 1;
    } else {
      const std::size_t comma = line.find(',', i);
      cells.emplace_back(
          trim(line.substr(i, comma == std::string_view::npos ? std::string_view::npos : comma - i)));
      if (comma == std::string_view::npos) break;
      i = comma + 1;
    }
  }
  return cells;
}

std::optional<double> to_number(std::string_view cell) {
  if (cell.empty()) return std::nullopt;
  const std::string s(cell);
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

bool is_index(const std::string& label) {
  return !label.empty() && label.size() <= 18 &&
         std::all_of(label.begin(), label.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string in_quotes(std::string_view s) {
  std::string r(1, '"');
  r.append(s);
  r.push_back('"');
  return r;
}

// `sphere:R`, `capsule:HALF_LENGTH,R`, `box:HX,HY,HZ` as a shape object of the scene
// format (named by the spec itself); nullopt when `spec` has no known kind prefix.
std::optional<nlohmann::json> inline_shape(const std::string& spec, const std::string& file,
                                           const std::string& field) {
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const std::string kind = spec.substr(0, colon);
  std::size_t want = 0;
  if (kind == "sphere")
    want = 1;
  else if (kind == "capsule")
    want = 2;
  else if (kind == "box")
    want = 3;
  else
    return std::nullopt;
  std::vector<double> v;
  std::string_view rest = std::string_view(spec).substr(colon + 1);
  while (true) {
    const std::size_t comma = rest.find(',');
    const auto x = to_number(trim(rest.substr(0, comma)));
    if (!x || !(*x > 0.0))
      throw InputError(file, field,
                       "shape " + in_quotes(spec) + ": sizes must be numbers > 0 (" + kind + ":" +
                           (want == 1   ? "R"
                            : want == 2 ? "HALF_LENGTH,R"
                                        : "HX,HY,HZ") +
                           ")");
    v.push_back(*x);
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  if (v.size() != want)
    throw InputError(file, field,
                     "shape " + in_quotes(spec) + " needs " + std::to_string(want) + " size(s), got " +
                         std::to_string(v.size()));
  nlohmann::json j = {{"name", spec}, {"kind", kind}};
  if (want == 1) j["radius"] = v[0];
  if (want == 2) {
    j["half_length"] = v[0];
    j["radius"] = v[1];
  }
  if (want == 3) j["half_extents"] = {v[0], v[1], v[2]};
  return j;
}

// The orientation after turning q0 at the constant world-frame angular velocity omega for
// s seconds: the formula of RotationPiece::orientation (ccd/motion/rotation.cpp), so the
// importer tracks the orientation the scene's motion model will produce.
Eigen::Quaterniond turned(const Eigen::Quaterniond& q0, const Vec3& omega, double s) {
  const double w = omega.norm();
  if (w == 0.0) return q0;
  const double half = 0.5 * w * s;
  const Vec3 axis = omega / w;
  const Eigen::Quaterniond step(std::cos(half), std::sin(half) * axis.x(), std::sin(half) * axis.y(),
                                std::sin(half) * axis.z());
  return (step * q0).normalized();
}

// The world-frame angular velocity that turns `from` into `to` in s seconds along the
// shortest arc (the rotation to * from^-1 with a non-negative scalar part).
Vec3 angular_velocity(const Eigen::Quaterniond& from, const Eigen::Quaterniond& to, double s) {
  Eigen::Quaterniond d = to * from.conjugate();
  if (d.w() < 0.0) d.coeffs() = -d.coeffs();
  const Vec3 axis = d.vec();
  const double n = axis.norm();
  if (n == 0.0) return Vec3::Zero();
  const double angle = 2.0 * std::atan2(n, d.w());
  return axis * (angle / (n * s));
}

// Where a body's frames, in file order, first go back in time: that frame and the one
// before it; nullopt when they never do. Rows may come in any order, so this is no error
// in itself; it is what to point at when the body's frames do not reach the file's first
// or last time (in a file written in time order, the line where t went wrong).
struct Backwards {
  const Frame* here;
  const Frame* before;
};
std::optional<Backwards> first_backwards(const std::vector<Frame>& frames_in_file_order) {
  for (std::size_t k = 1; k < frames_in_file_order.size(); ++k)
    if (frames_in_file_order[k].t < frames_in_file_order[k - 1].t)
      return Backwards{&frames_in_file_order[k], &frames_in_file_order[k - 1]};
  return std::nullopt;
}

[[noreturn]] void fail_at(const std::string& file, std::size_t line, const std::string& column,
                          const std::string& what) {
  throw InputError(file, "line " + std::to_string(line) + (column.empty() ? "" : ": " + column), what);
}

// The header row: where each known column is.
struct Header {
  std::array<int, kColumns> where;  ///< cell index of each column, -1 when absent
  std::size_t cells = 0;
  std::size_t line = 0;
  int quats = 0;  ///< how many of qw, qx, qy, qz (0 or 4)
};

// The rows so far, grouped by body label.
struct Rows {
  std::map<std::string, Track> tracks;
  std::vector<std::string> order;  ///< labels in order of first appearance
  std::size_t count = 0;
  double t_min = INFINITY, t_max = -INFINITY;
};

// Reads CSV lines and names the file and line of each failure.
class FrameReader {
 public:
  FrameReader(std::istream& csv, const std::string& file, const FrameImportOptions& options)
      : csv_(csv), file_(file), options_(options) {}

  [[noreturn]] void fail(std::size_t line, const std::string& column, const std::string& what) const {
    fail_at(file_, line, column, what);
  }

  Header header() {
    Header h;
    h.where.fill(-1);
    while (std::getline(csv_, text_)) {
      ++line_;
      if (trim(text_).empty()) continue;
      const auto split_cells = split(text_);
      if (!split_cells) fail(line_, "header", "unclosed quote");
      const auto& cells = *split_cells;
      h.cells = cells.size();
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto it = std::find(kNames.begin(), kNames.end(), cells[c]);
        if (it == kNames.end())
          fail(line_, "header",
               "unknown column " + in_quotes(cells[c]) +
                   " (known: body, t, x, y, z, radius, shape, qw, qx, qy, qz)");
        const auto k = static_cast<std::size_t>(it - kNames.begin());
        if (h.where[k] >= 0) fail(line_, "header", "column " + in_quotes(cells[c]) + " appears twice");
        h.where[k] = static_cast<int>(c);
      }
      break;
    }
    if (h.cells == 0) throw InputError(file_, "", "empty: needs a header row (body,t,x,y,z,radius)");
    h.line = line_;
    for (int k : {kBody, kT, kX, kY, kZ})
      if (h.where[static_cast<std::size_t>(k)] < 0)
        fail(h.line, "header", "missing column " + in_quotes(kNames[static_cast<std::size_t>(k)]));
    h.quats = (h.where[kQw] >= 0) + (h.where[kQx] >= 0) + (h.where[kQy] >= 0) + (h.where[kQz] >= 0);
    if (h.quats != 0 && h.quats != 4) fail(h.line, "header", "give all four of qw, qx, qy, qz or none");
    return h;
  }

  Rows rows(const Header& h) {
    Rows r;
    while (std::getline(csv_, text_)) {
      ++line_;
      if (trim(text_).empty()) continue;
      const auto split_cells = split(text_);
      if (!split_cells) fail(line_, "", "unclosed quote");
      row(h, *split_cells, r);
    }
    if (r.count == 0) fail(h.line, "", "no frames after the header");
    if (!(r.t_max > r.t_min))
      throw InputError(file_, "t", "needs at least two distinct times (the horizon would be 0)");
    return r;
  }

 private:
  // One row: its frame, added to its body's track (the body's radius or shape fixed by its
  // first row).
  void row(const Header& h, const std::vector<std::string>& cells, Rows& r) {
    if (cells.size() != h.cells)
      fail(line_, "",
           "has " + std::to_string(cells.size()) + " cells, the header " + std::to_string(h.cells));
    auto cell = [&](Column k) {
      return h.where[k] < 0 ? std::string_view()
                            : std::string_view(cells[static_cast<std::size_t>(h.where[k])]);
    };
    auto number = [&](Column k) {
      const std::string_view c = cell(k);
      const auto x = to_number(c);
      if (!x)
        fail(line_, std::string(kNames[k]),
             c.empty() ? "missing number" : "must be a finite number, got " + in_quotes(c));
      return *x;
    };
    const std::string label(cell(kBody));
    if (label.empty()) fail(line_, "body", "missing body label");
    Frame f;
    f.line = line_;
    f.t = number(kT);
    f.p = Vec3(number(kX), number(kY), number(kZ));
    if (h.quats == 4) {
      const Eigen::Quaterniond q(number(kQw), number(kQx), number(kQy), number(kQz));
      const double n = q.norm();
      if (!(std::fabs(n - 1.0) <= kQuaternionTolerance))
        fail(line_, "qw,qx,qy,qz", "must be a unit quaternion within 1e-6 (|q| = " + std::to_string(n) + ")");
      f.q = q.normalized();
    }
    const std::string shape(cell(kShape));
    std::optional<double> radius;
    if (!cell(kRadius).empty()) {
      radius = number(kRadius);
      if (!(*radius > 0.0)) fail(line_, "radius", "must be > 0");
      if (!shape.empty()) fail(line_, "radius", "not allowed with a shape (the shape gives the size)");
    }
    auto [it, fresh] = r.tracks.try_emplace(label);
    Track& tr = it->second;
    if (fresh) {
      r.order.push_back(label);
      tr.radius = radius;
      tr.shape = shape;
      tr.size_line = line_;
      if (!radius && shape.empty()) {
        if (!options_.radius)
          fail(line_, h.where[kRadius] >= 0 ? "radius" : "header",
               h.where[kRadius] >= 0 ? "missing number (or give a shape)"
                                     : "no radius or shape column: give --radius R for every body");
        tr.radius = options_.radius;
      }
    } else {
      if (shape != tr.shape)
        fail(line_, "shape",
             "body " + in_quotes(label) + " has shape " + in_quotes(tr.shape) + " on line " +
                 std::to_string(tr.size_line) + "; a body's shape cannot change");
      if (radius && tr.radius && *radius != *tr.radius)
        fail(line_, "radius",
             "body " + in_quotes(label) + " has radius " + std::to_string(*tr.radius) + " on line " +
                 std::to_string(tr.size_line) + "; a body's radius cannot change");
      if (!radius && shape.empty() && !options_.radius && h.where[kRadius] >= 0)
        fail(line_, "radius", "missing number (or give a shape)");
    }
    tr.frames.push_back(f);
    r.t_min = std::min(r.t_min, f.t);
    r.t_max = std::max(r.t_max, f.t);
    ++r.count;
  }

  std::istream& csv_;
  const std::string& file_;
  const FrameImportOptions& options_;
  std::string text_;
  std::size_t line_ = 0;
};

// Body order: numeric labels by value, others as strings; "07" and "7" would be two bodies
// with one index, so leading zeros are refused among numeric labels.
void sort_labels(Rows& r, const FrameReader& in) {
  const bool numeric = std::all_of(r.order.begin(), r.order.end(), is_index);
  std::sort(r.order.begin(), r.order.end(), [&](const std::string& a, const std::string& b) {
    if (numeric && a.size() != b.size()) return a.size() < b.size();  // no leading-zero ambiguity below
    return a < b;
  });
  if (numeric)
    for (const std::string& l : r.order)
      if (l.size() > 1 && l[0] == '0')
        in.fail(r.tracks[l].frames.front().line, "body", "label " + in_quotes(l) + " has a leading zero");
}

// Shapes: the named ones (--shapes), then inline specs as they are first used.
nlohmann::json collect_shapes(Rows& r, const FrameImportOptions& options, const std::string& file,
                              const FrameReader& in) {
  nlohmann::json shapes = options.shapes.is_array() ? options.shapes : nlohmann::json::array();
  std::unordered_set<std::string> known;  // names given or added: linear in the shapes
  for (const nlohmann::json& sh : shapes)
    if (sh.is_object() && sh.contains("name") && sh["name"].is_string())
      known.insert(sh["name"].get<std::string>());
  for (const std::string& l : r.order) {
    const Track& tr = r.tracks[l];
    if (tr.shape.empty() || !known.insert(tr.shape).second) continue;
    const auto j = inline_shape(tr.shape, file, "line " + std::to_string(tr.size_line) + ": shape");
    if (!j)
      in.fail(tr.size_line, "shape",
              "unknown shape " + in_quotes(tr.shape) +
                  " (not in --shapes; inline shapes are sphere:R, capsule:HALF_LENGTH,R, box:HX,HY,HZ)");
    shapes.push_back(*j);
  }
  return shapes;
}

// Sorts a body's frames by time and checks that they are distinct and span the file's
// first to last time.
void sort_track(Track& tr, const std::string& label, const Rows& r, const FrameReader& in) {
  std::optional<Frame> back_here, back_before;  // copies: the frames are sorted below
  if (const auto back = first_backwards(tr.frames)) {
    back_here = *back->here;
    back_before = *back->before;
  }
  // A body whose frames miss the file's first or last time: named at the line where its
  // time goes backwards, if it does, else at its first (last) frame.
  auto fail_span = [&](std::size_t line, const std::string& what) {
    if (back_here)
      in.fail(back_here->line, "t",
              "body " + in_quotes(label) + " goes backwards here (t = " + std::to_string(back_here->t) +
                  " after t = " + std::to_string(back_before->t) + " on line " +
                  std::to_string(back_before->line) + "), so it " + what);
    in.fail(line, "t", "body " + in_quotes(label) + " " + what);
  };
  std::sort(tr.frames.begin(), tr.frames.end(),
            [](const Frame& a, const Frame& b) { return a.t < b.t || (a.t == b.t && a.line < b.line); });
  for (std::size_t k = 1; k < tr.frames.size(); ++k)
    if (tr.frames[k].t == tr.frames[k - 1].t)
      in.fail(std::max(tr.frames[k].line, tr.frames[k - 1].line), "t",
              "body " + in_quotes(label) + " has two frames at t = " + std::to_string(tr.frames[k].t) +
                  " (lines " + std::to_string(std::min(tr.frames[k].line, tr.frames[k - 1].line)) + " and " +
                  std::to_string(std::max(tr.frames[k].line, tr.frames[k - 1].line)) + ")");
  if (tr.frames.front().t != r.t_min)
    fail_span(tr.frames.front().line, "starts at t = " + std::to_string(tr.frames.front().t) +
                                          ", after the file's first time " + std::to_string(r.t_min) +
                                          " (every body needs a frame at the first and the last time)");
  if (tr.frames.back().t != r.t_max)
    fail_span(tr.frames.back().line, "ends at t = " + std::to_string(tr.frames.back().t) +
                                         ", before the file's last time " + std::to_string(r.t_max) +
                                         " (every body needs a frame at the first and the last time)");
}

// The body of a sorted track: the velocity of each interval from the model's own position at
// its start (and, with orientations, the angular velocity from the model's own orientation).
std::pair<Body, RigidBody> track_body(const Track& tr, double t_min, bool orientations, std::int32_t shape) {
  std::vector<double> tau(tr.frames.size());
  for (std::size_t k = 0; k < tau.size(); ++k) tau[k] = tr.frames[k].t - t_min;
  Body b;
  b.radius = tr.radius.value_or(0.0);
  b.position = tr.frames.front().p;
  DdVec3 at(b.position);  // the model's position at tau[k]
  Vec3 previous{Vec3::Zero()};
  RigidBody rb;
  const bool shaped = shape != kNoShape;
  if (shaped) {
    rb.shape = shape;
    rb.orientation = tr.frames.front().q;
  }
  Eigen::Quaterniond q_at = rb.orientation;  // the model's orientation at tau[k]
  Vec3 previous_omega{Vec3::Zero()};
  for (std::size_t k = 0; k + 1 < tau.size(); ++k) {
    const Dd s_k = two_sum(tau[k + 1], -tau[k]);
    const double dt = s_k.value();
    Vec3 v;
    for (int a = 0; a < 3; ++a) v[a] = (Dd(tr.frames[k + 1].p[a]) - at[a]).value() / dt;
    if (k == 0)
      b.velocity = v;
    else if (v != previous)
      b.velocity_changes.push_back({tau[k], v});
    for (int a = 0; a < 3; ++a) at[a] = at[a] + Dd(v[a]) * s_k;
    previous = v;
    if (shaped && orientations) {
      const Vec3 w = angular_velocity(q_at, tr.frames[k + 1].q, dt);
      if (k == 0)
        rb.angular_velocity = w;
      else if (w != previous_omega)
        rb.angular_velocity_changes.push_back({tau[k], w});
      q_at = turned(q_at, w, tau[k + 1] - tau[k]);
      previous_omega = w;
    }
  }
  return {std::move(b), std::move(rb)};
}

}  // namespace

FrameImport import_frames(std::istream& csv, const std::string& file, const FrameImportOptions& options) {
  FrameReader in(csv, file, options);
  const Header header = in.header();
  Rows rows = in.rows(header);
  sort_labels(rows, in);
  const nlohmann::json shapes = collect_shapes(rows, options, file, in);
  FrameImport out;
  out.time_origin = rows.t_min;
  out.frames = rows.count;
  Scene& s = out.scene;
  s.horizon = rows.t_max - rows.t_min;
  if (!shapes.empty()) {  // parsed and checked as a scene's shapes
    const nlohmann::json holder = {
        {"format", kSceneFormat}, {"horizon", 1.0}, {"shapes", shapes}, {"bodies", nlohmann::json::array()}};
    s.shapes = scene_from_json(holder, options.shapes_file).shapes;
  }
  std::unordered_map<std::string, std::size_t> shape_index;
  for (std::size_t k = 0; k < s.shapes.size(); ++k) shape_index.emplace(s.shapes[k].name, k);
  const bool any_shape = std::any_of(rows.order.begin(), rows.order.end(),
                                     [&](const std::string& l) { return !rows.tracks[l].shape.empty(); });
  for (const std::string& label : rows.order) {
    Track& tr = rows.tracks[label];
    sort_track(tr, label, rows, in);
    const std::int32_t shape =
        tr.shape.empty() ? kNoShape : static_cast<std::int32_t>(shape_index.at(tr.shape));
    auto [b, rb] = track_body(tr, rows.t_min, header.quats == 4, shape);
    if (any_shape)
      s.add_rigid_body(std::move(b), std::move(rb));
    else
      s.bodies.push_back(std::move(b));
  }
  out.labels = rows.order;
  validate_scene(s, file);
  return out;
}

}  // namespace ccd
