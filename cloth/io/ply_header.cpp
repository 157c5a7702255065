#include "ply_header.hpp"

#include <cloth/io/quoted_word.hpp>

#include <ccd/io/input_error.hpp>

#include <array>
#include <charconv>
#include <optional>

namespace ccd::cloth {

namespace {

struct TypeName {
  const char* name;
  PlyType type;
};

constexpr std::array<TypeName, 16> kTypeNames{{
    {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
}};

std::optional<PlyType> type_named(std::string_view s) {
  for (const TypeName& t : kTypeNames)
    if (s == t.name) return t.type;
  return std::nullopt;
}

// The words of a header line, split at spaces and tabs.
std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  PlyHeader parse() {
    if (bytes_.empty()) throw InputError(file_, "", "empty file");
    if (!has_ply_magic(bytes_)) throw InputError(file_, "", "not a PLY file (the first line is not 'ply')");
    std::size_t pos = bytes_[3] == '\n' ? 4 : 5;
    line_ = 1;
    while (true) {
      const std::size_t eol = bytes_.find('\n', pos);
      if (eol == std::string_view::npos) throw InputError(file_, "header", "no end_header line (the file ends in the header)");
      std::string_view line = bytes_.substr(pos, eol - pos);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      pos = eol + 1;
      ++line_;
      if (line_entry(line)) break;
    }
    if (!format_) throw InputError(file_, "header", "no format line");
    out_.body_offset = pos;
    out_.lines = line_;
    return out_;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_, "header line " + std::to_string(line_), what);
  }

  // One header line; true at end_header.
  bool line_entry(std::string_view line) {
    const std::vector<std::string_view> w = words_of(line);
    if (w.empty()) return false;  // a blank line
    if (w[0] == "comment" || w[0] == "obj_info") return false;
    for (char c : line)
      if ((c < 0x20 || c >= 0x7f) && c != '\t') fail("a byte that is not printable ASCII in a header line");
    if (w[0] == "end_header") {
      if (w.size() != 1) fail("text after end_header");
      return true;
    }
    if (w[0] == "format") {
      format_line(w);
    } else if (w[0] == "element") {
      element_line(w);
    } else if (w[0] == "property") {
      property_line(w);
    } else {
      fail("unknown keyword " + quoted_word(w[0]) + " (format, element, property, comment, obj_info, end_header)");
    }
    return false;
  }

  void format_line(const std::vector<std::string_view>& w) {
    if (format_) fail("a second format line");
    if (w.size() != 3) fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    if (w[1] == "ascii") {
      out_.format = PlyFormat::Ascii;
    } else if (w[1] == "binary_little_endian") {
      out_.format = PlyFormat::BinaryLittleEndian;
    } else if (w[1] == "binary_big_endian") {
      out_.format = PlyFormat::BinaryBigEndian;
    } else {
      fail("unknown format " + quoted_word(w[1]) + " (ascii, binary_little_endian or binary_big_endian)");
    }
    if (w[2] != "1.0" && w[2] != "1") fail("unsupported format version " + quoted_word(w[2]) + " (1.0 is read)");
    format_ = true;
  }

  void element_line(const std::vector<std::string_view>& w) {
    if (w.size() != 3) fail("expected 'element NAME COUNT'");
    PlyElement e;
    e.name = std::string(w[1]);
    const char* end = w[2].data() + w[2].size();
    const auto [ptr, ec] = std::from_chars(w[2].data(), end, e.count);
    if (ec != std::errc() || ptr != end)
      fail("element " + quoted_word(w[1]) + ": count " + quoted_word(w[2]) + " is not an integer from 0 to 2^64 - 1");
    for (const PlyElement& other : out_.elements)
      if (other.name == e.name && (e.name == "vertex" || e.name == "face")) fail("a second element " + quoted_word(w[1]));
    out_.elements.push_back(std::move(e));
  }

  PlyType type_word(std::string_view word) const {
    const std::optional<PlyType> t = type_named(word);
    if (!t) fail("unknown type " + quoted_word(word) + " (char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
    return *t;
  }

  void property_line(const std::vector<std::string_view>& w) {
    if (out_.elements.empty()) fail("property before any element");
    PlyProperty p;
    if (w.size() >= 2 && w[1] == "list") {
      if (w.size() != 5) fail("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
      p.list = true;
      p.count_type = type_word(w[2]);
      if (!ply_type_is_integer(p.count_type)) fail("list " + quoted_word(w[4]) + ": the count type " + quoted_word(w[2]) + " is not an integer type");
      p.type = type_word(w[3]);
      p.name = std::string(w[4]);
    } else {
      if (w.size() != 3) fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
      p.type = type_word(w[1]);
      p.name = std::string(w[2]);
    }
    PlyElement& e = out_.elements.back();
    for (const PlyProperty& other : e.properties)
      if (other.name == p.name) fail("property " + quoted_word(p.name) + " appears twice in element " + quoted_word(e.name));
    e.properties.push_back(std::move(p));
  }

  std::string_view bytes_;
  const std::string& file_;
  PlyHeader out_;
  std::size_t line_ = 0;
  bool format_ = false;
};

}  // namespace

std::size_t ply_type_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 8;
}

bool ply_type_is_integer(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

const char* ply_type_name(PlyType t) {
  switch (t) {
    case PlyType::Int8: return "char";
    case PlyType::UInt8: return "uchar";
    case PlyType::Int16: return "short";
    case PlyType::UInt16: return "ushort";
    case PlyType::Int32: return "int";
    case PlyType::UInt32: return "uint";
    case PlyType::Float32: return "float";
    case PlyType::Float64: return "double";
  }
  return "double";
}

bool has_ply_magic(std::string_view bytes) {
  return bytes.substr(0, 4) == "ply\n" || bytes.substr(0, 5) == "ply\r\n";
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& file) {
  return HeaderParser(bytes, file).parse();
}

}  // namespace ccd::cloth
