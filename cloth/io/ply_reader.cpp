#include "ply_reader.hpp"

#include <cloth/io/ply_header.hpp>
#include <cloth/io/quoted_word.hpp>
#include <cloth/io/regular_file.hpp>

#include <ccd/io/input_error.hpp>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

namespace ccd::cloth {

namespace {

// What the reader does with a property of the vertex or face element.
enum class Role : std::uint8_t { Skip, X, Y, Z, Indices };

struct ElementPlan {
  const PlyElement* element = nullptr;
  std::vector<Role> roles;  // one per property
  bool vertex = false, face = false;
};

std::string where(const PlyElement& e, std::uint64_t i) { return e.name + " " + std::to_string(i); }

const char* axis_name(Role r) { return r == Role::X ? "x" : r == Role::Y ? "y" : "z"; }

// The roles of every element's properties; the vertex and face elements must be there.
std::vector<ElementPlan> plan_of(const PlyHeader& h, const std::string& file) {
  std::vector<ElementPlan> plans;
  bool has_vertex = false, has_face = false;
  for (const PlyElement& e : h.elements) {
    ElementPlan plan;
    plan.element = &e;
    plan.vertex = e.name == "vertex";
    plan.face = e.name == "face";
    int found = 0;
    for (const PlyProperty& p : e.properties) {
      Role r = Role::Skip;
      if (plan.vertex && (p.name == "x" || p.name == "y" || p.name == "z")) {
        if (p.list) throw InputError(file, "header", "vertex property '" + p.name + "' is a list, not a number");
        r = p.name == "x" ? Role::X : p.name == "y" ? Role::Y : Role::Z;
        found |= 1 << (static_cast<int>(r) - 1);
      } else if (plan.face && (p.name == "vertex_indices" || p.name == "vertex_index") && found == 0) {
        if (!p.list) throw InputError(file, "header", "face property '" + p.name + "' is not a list");
        if (!ply_type_is_integer(p.type))
          throw InputError(file, "header", "face property '" + p.name + "': the index type " + ply_type_name(p.type) + " is not an integer type");
        r = Role::Indices;
        found = 7;
      }
      plan.roles.push_back(r);
    }
    for (int k = 0; k < 3 && plan.vertex; ++k)
      if (!(found & (1 << k))) throw InputError(file, "header", std::string("the vertex element has no property '") + "xyz"[k] + "'");
    if (plan.face && found != 7) throw InputError(file, "header", "the face element has no list property vertex_indices (or vertex_index)");
    has_vertex |= plan.vertex;
    has_face |= plan.face;
    plans.push_back(std::move(plan));
  }
  if (!has_vertex) throw InputError(file, "header", "no vertex element");
  if (!has_face) throw InputError(file, "header", "no face element");
  return plans;
}

// The fewest bytes one element can take: binary, its scalars and list counts (3 items for
// the face's index list, the only length read); ascii, two bytes per value (a digit and a
// separator).
std::uint64_t min_element_bytes(const ElementPlan& plan, PlyFormat format) {
  std::uint64_t bytes = 0;
  const auto& props = plan.element->properties;
  for (std::size_t k = 0; k < props.size(); ++k) {
    const bool indices = plan.roles[k] == Role::Indices;
    if (format == PlyFormat::Ascii) {
      bytes += indices ? 8 : 2;
    } else if (!props[k].list) {
      bytes += ply_type_size(props[k].type);
    } else {
      bytes += ply_type_size(props[k].count_type) + (indices ? 3 * ply_type_size(props[k].type) : 0);
    }
  }
  return bytes;
}

// Refuses counts that cannot fit in the body, before anything is allocated for them.
void check_counts(const std::vector<ElementPlan>& plans, PlyFormat format, std::uint64_t body, const std::string& file) {
  // An ascii body may omit the separator after its last value.
  std::uint64_t left = format == PlyFormat::Ascii ? body + 1 : body;
  for (const ElementPlan& plan : plans) {
    const PlyElement& e = *plan.element;
    const std::uint64_t each = min_element_bytes(plan, format);
    if (each != 0 && e.count > left / each)
      throw InputError(file, "element " + e.name,
                       "the header declares " + std::to_string(e.count) + ", of at least " + std::to_string(each) +
                           " bytes each, but only " + std::to_string(left) + " bytes of the file are left for them (truncated or corrupt file)");
    left -= each * e.count;
    if (plan.vertex && e.count > std::numeric_limits<std::uint32_t>::max())
      throw InputError(file, "element vertex", "more than 4294967295 vertices");
  }
}

void check_coordinate(double v, Role r, const PlyElement& e, std::uint64_t i, const std::string& file) {
  if (std::isnan(v)) throw InputError(file, where(e, i), std::string(axis_name(r)) + " is NaN");
  if (std::isinf(v)) throw InputError(file, where(e, i), std::string(axis_name(r)) + " is infinite");
}

std::uint32_t checked_index(std::int64_t v, std::uint64_t vertices, std::uint64_t i, const std::string& file) {
  if (v < 0) throw InputError(file, "face " + std::to_string(i), "vertex index " + std::to_string(v) + " is negative");
  if (static_cast<std::uint64_t>(v) >= vertices)
    throw InputError(file, "face " + std::to_string(i),
                     "vertex index " + std::to_string(v) + " out of range (the file has " + std::to_string(vertices) + " vertices)");
  return static_cast<std::uint32_t>(v);
}

[[noreturn]] void not_a_triangle(std::int64_t n, std::uint64_t i, const std::string& file) {
  throw InputError(file, "face " + std::to_string(i),
                   "has " + std::to_string(n) + " vertices; only triangles are read");
}

// ---- binary ----

template <class U>
U load_unsigned(const char* p, bool swap) {
  U u;
  std::memcpy(&u, p, sizeof(U));
  if (swap) {
    if constexpr (sizeof(U) == 2) u = static_cast<U>(__builtin_bswap16(u));
    if constexpr (sizeof(U) == 4) u = __builtin_bswap32(u);
    if constexpr (sizeof(U) == 8) u = __builtin_bswap64(u);
  }
  return u;
}

class BinaryBody {
 public:
  BinaryBody(std::string_view body, bool swap) : p_(body.data()), end_(body.data() + body.size()), swap_(swap) {}

  bool has(std::uint64_t n) const { return static_cast<std::uint64_t>(end_ - p_) >= n; }
  std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
  void skip(std::size_t n) { p_ += n; }

  // The next value, as a double (exact for every type). The caller checked has().
  double number(PlyType t) {
    if (t == PlyType::Float32) return static_cast<double>(std::bit_cast<float>(next<std::uint32_t>()));
    if (t == PlyType::Float64) return std::bit_cast<double>(next<std::uint64_t>());
    return static_cast<double>(integer(t));
  }

  // The next value of an integer type. The caller checked has().
  std::int64_t integer(PlyType t) {
    switch (t) {
      case PlyType::Int8: return static_cast<std::int8_t>(next<std::uint8_t>());
      case PlyType::UInt8: return next<std::uint8_t>();
      case PlyType::Int16: return static_cast<std::int16_t>(next<std::uint16_t>());
      case PlyType::UInt16: return next<std::uint16_t>();
      case PlyType::Int32: return static_cast<std::int32_t>(next<std::uint32_t>());
      case PlyType::UInt32: return next<std::uint32_t>();
      case PlyType::Float32:
      case PlyType::Float64: break;
    }
    return 0;  // not reached: header checks made every count and index type an integer type
  }

 private:
  template <class U>
  U next() {
    const U u = load_unsigned<U>(p_, swap_);
    p_ += sizeof(U);
    return u;
  }

  const char* p_;
  const char* end_;
  bool swap_;
};

[[noreturn]] void truncated(const PlyElement& e, std::uint64_t i, const std::string& file) {
  throw InputError(file, where(e, i), "the file ends inside this " + e.name + " (truncated body)");
}

void read_binary_element(BinaryBody& in, const ElementPlan& plan, std::uint64_t vertices, TriangleMesh& mesh, const std::string& file) {
  const PlyElement& e = *plan.element;
  const auto& props = e.properties;
  for (std::uint64_t i = 0; i < e.count; ++i) {
    Vec3 xyz = Vec3::Zero();
    for (std::size_t k = 0; k < props.size(); ++k) {
      const PlyProperty& p = props[k];
      const Role role = plan.roles[k];
      if (!p.list) {
        const std::size_t size = ply_type_size(p.type);
        if (!in.has(size)) truncated(e, i, file);
        if (role == Role::Skip) {
          in.skip(size);
        } else {
          const double v = in.number(p.type);
          check_coordinate(v, role, e, i, file);
          xyz[role == Role::X ? 0 : role == Role::Y ? 1 : 2] = v;
        }
        continue;
      }
      if (!in.has(ply_type_size(p.count_type))) truncated(e, i, file);
      const std::int64_t n = in.integer(p.count_type);
      const std::size_t item = ply_type_size(p.type);
      if (role == Role::Indices) {
        if (n != 3) not_a_triangle(n, i, file);
        if (!in.has(3 * item)) truncated(e, i, file);
        for (auto& index : mesh.faces[i]) index = checked_index(in.integer(p.type), vertices, i, file);
        continue;
      }
      if (n < 0) throw InputError(file, where(e, i), "list '" + p.name + "' has a negative count " + std::to_string(n));
      if (static_cast<std::uint64_t>(n) > in.left() / item) truncated(e, i, file);
      in.skip(static_cast<std::size_t>(n) * item);
    }
    if (plan.vertex) mesh.vertices[i] = xyz;
  }
}

// ---- ascii ----

class AsciiBody {
 public:
  AsciiBody(std::string_view body, std::size_t first_line, const std::string& file) : s_(body), line_(first_line), file_(file) {}

  // Moves to the next line that is not blank; false at the end of the text.
  bool next_line() {
    while (true) {
      std::size_t i = pos_;
      while (i < s_.size() && (s_[i] == ' ' || s_[i] == '\t' || s_[i] == '\r')) ++i;
      if (i == s_.size()) {
        pos_ = i;
        return false;
      }
      if (s_[i] != '\n') return true;
      pos_ = i + 1;
      ++line_;
    }
  }

  // The next value of the line; empty at its end.
  std::string_view token() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < s_.size() && s_[pos_] != ' ' && s_[pos_] != '\t' && s_[pos_] != '\n' && s_[pos_] != '\r') ++pos_;
    return s_.substr(start, pos_ - start);
  }

  // Ends the element's line: only white space may be left on it.
  void end_line(const PlyElement& e, std::uint64_t i) {
    const std::string_view extra = token();
    if (!extra.empty()) throw InputError(file_, where(e, i), "extra value " + quoted_word(extra) + " at the end of the line (line " + std::to_string(line_) + ")");
    while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;  // only '\r' is left
    if (pos_ < s_.size()) ++pos_;
    ++line_;
  }

  std::size_t line() const { return line_; }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  std::size_t line_;
  const std::string& file_;
};

// Parses one ascii value of type t: a decimal number (an optional '+' is allowed) in the
// type's range; float values are read as floats, then widened.
double ascii_number(std::string_view tok, PlyType t, const std::string& file, const PlyElement& e, std::uint64_t i,
                    const std::string& name) {
  if (tok.empty()) throw InputError(file, where(e, i), "the line ends before property '" + name + "'");
  std::string_view digits = tok;
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  const char* first = digits.data();
  const char* last = digits.data() + digits.size();
  std::from_chars_result r{};
  double value = 0;
  if (t == PlyType::Float32) {
    float f = 0;
    r = std::from_chars(first, last, f);
    value = f;
  } else if (t == PlyType::Float64) {
    r = std::from_chars(first, last, value);
  } else {
    std::int64_t n = 0;
    r = std::from_chars(first, last, n);
    value = static_cast<double>(n);
    const bool fits = t == PlyType::Int8     ? n >= -128 && n <= 127
                      : t == PlyType::UInt8  ? n >= 0 && n <= 255
                      : t == PlyType::Int16  ? n >= -32768 && n <= 32767
                      : t == PlyType::UInt16 ? n >= 0 && n <= 65535
                      : t == PlyType::Int32  ? n >= std::numeric_limits<std::int32_t>::min() && n <= std::numeric_limits<std::int32_t>::max()
                                             : n >= 0 && n <= std::numeric_limits<std::uint32_t>::max();
    if (r.ec == std::errc() && r.ptr == last && !fits) r.ec = std::errc::result_out_of_range;
  }
  if (r.ec == std::errc::result_out_of_range && r.ptr == last)
    throw InputError(file, where(e, i), name + " " + quoted_word(tok) + " is out of the range of " + ply_type_name(t));
  if (r.ec != std::errc() || r.ptr != last)
    throw InputError(file, where(e, i), name + " is not a number of type " + ply_type_name(t) + ": " + quoted_word(tok));
  return value;
}

void read_ascii_element(AsciiBody& in, const ElementPlan& plan, std::uint64_t vertices, TriangleMesh& mesh, const std::string& file) {
  const PlyElement& e = *plan.element;
  const auto& props = e.properties;
  for (std::uint64_t i = 0; i < e.count; ++i) {
    if (!in.next_line())
      throw InputError(file, where(e, i), "the file ends before this " + e.name + " (truncated body: the header declares " + std::to_string(e.count) + ")");
    Vec3 xyz = Vec3::Zero();
    for (std::size_t k = 0; k < props.size(); ++k) {
      const PlyProperty& p = props[k];
      const Role role = plan.roles[k];
      if (!p.list) {
        const double v = ascii_number(in.token(), p.type, file, e, i, p.name);
        if (role != Role::Skip) {
          check_coordinate(v, role, e, i, file);
          xyz[role == Role::X ? 0 : role == Role::Y ? 1 : 2] = v;
        }
        continue;
      }
      const auto n = static_cast<std::int64_t>(ascii_number(in.token(), p.count_type, file, e, i, p.name));
      if (role == Role::Indices) {
        if (n != 3) not_a_triangle(n, i, file);
        for (auto& index : mesh.faces[i])
          index = checked_index(static_cast<std::int64_t>(ascii_number(in.token(), p.type, file, e, i, p.name)), vertices, i, file);
        continue;
      }
      if (n < 0) throw InputError(file, where(e, i), "list '" + p.name + "' has a negative count " + std::to_string(n));
      for (std::int64_t j = 0; j < n; ++j) ascii_number(in.token(), p.type, file, e, i, p.name);
    }
    in.end_line(e, i);
    if (plan.vertex) mesh.vertices[i] = xyz;
  }
}

}  // namespace

TriangleMesh parse_ply(std::string_view bytes, const std::string& file) {
  const PlyHeader header = parse_ply_header(bytes, file);
  const std::vector<ElementPlan> plans = plan_of(header, file);
  const std::string_view body = bytes.substr(header.body_offset);
  check_counts(plans, header.format, body.size(), file);
  std::uint64_t vertices = 0;
  TriangleMesh mesh;
  for (const ElementPlan& plan : plans) {
    if (plan.vertex) {
      vertices = plan.element->count;
      mesh.vertices.resize(static_cast<std::size_t>(vertices));
    }
    if (plan.face) mesh.faces.resize(static_cast<std::size_t>(plan.element->count));
  }
  if (header.format == PlyFormat::Ascii) {
    AsciiBody in(body, header.lines + 1, file);
    for (const ElementPlan& plan : plans)
      if (!plan.element->properties.empty()) read_ascii_element(in, plan, vertices, mesh, file);
    if (in.next_line()) {
      const std::size_t line = in.line();
      throw InputError(file, "line " + std::to_string(line), "text after the last element: " + quoted_word(in.token()));
    }
  } else {
    BinaryBody in(body, (header.format == PlyFormat::BinaryBigEndian) == (std::endian::native == std::endian::little));
    for (const ElementPlan& plan : plans)
      if (!plan.element->properties.empty()) read_binary_element(in, plan, vertices, mesh, file);
    if (in.left() != 0)
      throw InputError(file, "", std::to_string(in.left()) + " bytes after the last element (the header declares fewer elements than the file holds)");
  }
  return mesh;
}

TriangleMesh read_ply(const std::string& path) { return parse_ply(read_regular_file(path), path); }

}  // namespace ccd::cloth
