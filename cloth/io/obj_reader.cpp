#include "obj_reader.hpp"

#include <cloth/io/quoted_word.hpp>
#include <cloth/io/regular_file.hpp>

#include <ccd/io/input_error.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace ccd::cloth {

namespace {

// Statements that carry nothing a triangle mesh keeps.
constexpr std::array<std::string_view, 38> kSkipped{
    "vt",     "vn",    "vp",       "o",        "g",     "s",        "usemtl",   "mtllib",  "l",     "p",
    "cstype", "deg",   "bmat",     "step",     "curv",  "curv2",    "surf",     "parm",    "trim",  "hole",
    "scrv",   "sp",    "end",      "con",      "mg",    "bevel",    "c_interp", "d_interp", "lod",  "maplib",
    "usemap", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh", "vertex_weights"};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The words of one logical line (continuations joined, the comment cut off).
class Words {
 public:
  explicit Words(std::string_view line) : s_(line) {}
  std::string_view next() {
    while (i_ < s_.size() && is_space(s_[i_])) ++i_;
    const std::size_t start = i_;
    while (i_ < s_.size() && !is_space(s_[i_])) ++i_;
    return s_.substr(start, i_ - start);
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
};

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  TriangleMesh parse() {
    if (text_.empty()) throw InputError(file_, "", "empty file");
    std::string joined;  // a line with continuations, when one has them
    while (pos_ < text_.size()) {
      line_no_ = next_line_no_;
      std::string_view line = physical_line();
      while (ends_with_backslash(line) && pos_ < text_.size()) {
        joined.assign(line.substr(0, line.find_last_of('\\')));
        joined += ' ';
        std::string_view more = physical_line();
        while (true) {
          const bool again = ends_with_backslash(more) && pos_ < text_.size();
          joined.append(again ? more.substr(0, more.find_last_of('\\')) : more);
          if (!again) break;
          joined += ' ';
          more = physical_line();
        }
        line = joined;
      }
      statement(line);
    }
    if (mesh_.vertices.empty()) throw InputError(file_, "", "no vertex ('v' line): not an OBJ mesh");
    for (const auto& [f, line] : forward_)
      for (std::uint32_t v : mesh_.faces[f])
        if (v >= mesh_.vertices.size()) out_of_range(line, std::uint64_t{v} + 1);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, "line " + std::to_string(line_no_), what); }

  [[noreturn]] void out_of_range(std::size_t line, std::uint64_t index) const {
    throw InputError(file_, "line " + std::to_string(line),
                     "vertex index " + std::to_string(index) + " out of range (the file has " + std::to_string(mesh_.vertices.size()) + " vertices)");
  }

  static bool ends_with_backslash(std::string_view line) {
    std::size_t n = line.size();
    while (n > 0 && is_space(line[n - 1])) --n;
    return n > 0 && line[n - 1] == '\\';
  }

  // The next physical line without its end and without its comment.
  std::string_view physical_line() {
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++next_line_no_;
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
  }

  void statement(std::string_view line) {
    Words words(line);
    const std::string_view keyword = words.next();
    if (keyword.empty()) return;
    if (keyword == "v") return vertex(words);
    if (keyword == "f") return face(words);
    for (std::string_view s : kSkipped)
      if (keyword == s) return;
    fail("unknown statement " + quoted_word(keyword));
  }

  void vertex(Words& words) {
    std::array<double, 7> values{};
    std::size_t n = 0;
    for (std::string_view w = words.next(); !w.empty(); w = words.next()) {
      if (n == values.size()) fail("a vertex has more than 7 numbers (x y z, x y z w or x y z r g b)");
      values[n] = number(w, n + 1);
      ++n;
    }
    if (n != 3 && n != 4 && n != 6 && n != 7)
      fail("a vertex has " + std::to_string(n) + " numbers; expected x y z, x y z w or x y z r g b");
    static constexpr std::array<const char*, 3> kAxis{"x", "y", "z"};
    for (std::size_t k = 0; k < 3; ++k) {
      if (std::isnan(values[k])) fail(std::string(kAxis[k]) + " is NaN");
      if (std::isinf(values[k])) fail(std::string(kAxis[k]) + " is infinite");
    }
    if (mesh_.vertices.size() == std::numeric_limits<std::uint32_t>::max()) fail("more than 4294967295 vertices");
    mesh_.vertices.emplace_back(values[0], values[1], values[2]);
  }

  double number(std::string_view w, std::size_t position) const {
    std::string_view digits = w;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
    double v = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    static constexpr std::array<const char*, 7> kNames{"x", "y", "z", "value 4", "value 5", "value 6", "value 7"};
    const char* name = kNames[position - 1];
    if (ec == std::errc::result_out_of_range && ptr == digits.data() + digits.size())
      fail(std::string(name) + " " + quoted_word(w) + " is beyond the range of a double");
    if (ec != std::errc() || ptr != digits.data() + digits.size()) fail(std::string(name) + " is not a number: " + quoted_word(w));
    return v;
  }

  // An index of a face corner: an optional '-' and digits.
  std::int64_t integer(std::string_view w, std::string_view corner) const {
    std::int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || ptr != w.data() + w.size() || w.empty()) fail("face corner " + quoted_word(corner) + " is not v, v/vt, v//vn or v/vt/vn with integer indices");
    return v;
  }

  void face(Words& words) {
    std::array<std::uint32_t, 3> corners{};
    bool forward = false;
    std::size_t n = 0;
    for (std::string_view w = words.next(); !w.empty(); w = words.next(), ++n) {
      const std::size_t slash = w.find('/');
      const std::int64_t v = integer(w.substr(0, slash), w);
      if (slash != std::string_view::npos) {
        const std::string_view rest = w.substr(slash + 1);
        const std::size_t slash2 = rest.find('/');
        const std::string_view texture = rest.substr(0, slash2);
        if (!texture.empty() || slash2 == std::string_view::npos) integer(texture, w);
        if (slash2 != std::string_view::npos) integer(rest.substr(slash2 + 1), w);
      }
      if (n >= 3) continue;  // counted, refused below
      corners[n] = vertex_index(v, forward);
    }
    if (n != 3) fail("face has " + std::to_string(n) + " vertices; only triangles are read");
    mesh_.faces.push_back(corners);
    if (forward) forward_.emplace_back(mesh_.faces.size() - 1, line_no_);
  }

  // The 0-based vertex of an OBJ index; positive ones beyond the vertices so far are
  // checked at the end of the file (`forward`).
  std::uint32_t vertex_index(std::int64_t v, bool& forward) const {
    const auto defined = static_cast<std::int64_t>(mesh_.vertices.size());
    if (v == 0) fail("vertex index 0 (OBJ indices start at 1; negative ones count back from the last vertex)");
    if (v < 0) {
      if (-v > defined)
        fail("vertex index " + std::to_string(v) + " out of range (" + std::to_string(defined) + " vertices before this line)");
      return static_cast<std::uint32_t>(defined + v);
    }
    if (v > std::numeric_limits<std::uint32_t>::max()) fail("vertex index " + std::to_string(v) + " out of range (more than 4294967295)");
    forward |= v > defined;
    return static_cast<std::uint32_t>(v - 1);
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  std::size_t line_no_ = 0, next_line_no_ = 1;
  TriangleMesh mesh_;
  std::vector<std::pair<std::size_t, std::size_t>> forward_;  // (face, line): faces naming later vertices
};

}  // namespace

TriangleMesh parse_obj(std::string_view text, const std::string& file) { return ObjParser(text, file).parse(); }

TriangleMesh read_obj(const std::string& path) { return parse_obj(read_regular_file(path), path); }

}  // namespace ccd::cloth
