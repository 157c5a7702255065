#pragma once
// Shared by the mesh reader and writer tests: two reference meshes, a bit-for-bit
// comparison, and a PLY composer that writes any header and body (types, lists, extra
// elements, byte orders, line ends) independently of the writer under test.
#include <cloth/io/ply_header.hpp>
#include <cloth/io/triangle_mesh.hpp>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace meshtest {

using ccd::Vec3;
using ccd::cloth::PlyFormat;
using ccd::cloth::PlyType;
using ccd::cloth::TriangleMesh;

// Dyadic coordinates that floats hold exactly (24-bit significands): halves, eighths,
// negatives, -0, 2^20 + 1/2 (22 bits), 2^-30, 1024.75.
inline TriangleMesh dyadic_mesh() {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0),         Vec3(1, 0, 0),          Vec3(0, 1, 0),      Vec3(0.5, 0.5, -0.125),
                Vec3(-0.0, 3.75, -2),  Vec3(1048576.5, -1, 2), Vec3(std::ldexp(1.0, -30), 1024.75, -7.5)};
  m.faces = {{0, 1, 2}, {1, 3, 2}, {3, 4, 5}, {6, 5, 4}, {0, 6, 2}};
  return m;
}

// Doubles that floats cannot hold: 2^20 + 2^-30 (51 bits), 0.1, the smallest subnormal,
// 1e-300, -1e300, the largest double, 1/3.
inline TriangleMesh double_mesh() {
  TriangleMesh m;
  const double far = std::ldexp(1.0, 20) + std::ldexp(1.0, -30);
  m.vertices = {Vec3(far, far, -far),
                Vec3(0.1, 0.2, 0.3),
                Vec3(std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(), 1e-300),
                Vec3(-1e300, std::numeric_limits<double>::max(), 1.0 / 3.0),
                Vec3(far + 1, -0.0, 2.5)};
  m.faces = {{0, 1, 2}, {2, 3, 4}, {4, 0, 1}};
  return m;
}

// Every coordinate bit for bit (-0 differs from 0) and every face.
inline bool same_bits(const TriangleMesh& a, const TriangleMesh& b) {
  if (a.vertices.size() != b.vertices.size() || a.faces != b.faces) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (std::bit_cast<std::uint64_t>(a.vertices[i][k]) != std::bit_cast<std::uint64_t>(b.vertices[i][k])) return false;
  return true;
}

// The mesh with every coordinate rounded to the nearest float. The float goes through a
// volatile: GCC 12 at -O3 (SLP vectorization of the x and y lanes) dropped the
// double -> float -> double round trip of two of the three coordinates, written in place or
// through a float array, so the expected values were the unrounded doubles.
inline double nearest_float(double x) {
  volatile float f = static_cast<float>(x);
  return static_cast<double>(f);
}

inline TriangleMesh as_floats(TriangleMesh m) {
  for (Vec3& v : m.vertices)
    for (int k = 0; k < 3; ++k) v[k] = nearest_float(v[k]);
  return m;
}

struct Prop {
  std::string name;
  PlyType type = PlyType::Float32;
  bool list = false;
  PlyType count_type = PlyType::UInt8;
};

// One element: its properties and, per instance, the values of each property (one value
// for a scalar, the items for a list).
struct Elem {
  std::string name;
  std::vector<Prop> props;
  std::vector<std::vector<std::vector<double>>> rows;
};

inline const char* type_word(PlyType t, bool long_names) {
  static constexpr std::array<const char*, 8> kShort{"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  static constexpr std::array<const char*, 8> kLong{"int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  return (long_names ? kLong : kShort)[static_cast<std::size_t>(t)];
}

inline void put_ascii(std::string& out, double v, PlyType t) {
  std::array<char, 40> buf{};
  char* end = nullptr;
  if (t == PlyType::Float64) {
    end = std::to_chars(buf.data(), buf.data() + buf.size(), v).ptr;
  } else if (t == PlyType::Float32) {
    end = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<float>(v)).ptr;
  } else {
    end = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<std::int64_t>(v)).ptr;
  }
  out.append(buf.data(), end);
}

inline void put_binary(std::string& out, double v, PlyType t, bool big) {
  std::array<unsigned char, 8> b{};
  std::size_t n = ccd::cloth::ply_type_size(t);
  std::uint64_t u = 0;
  switch (t) {
    case PlyType::Int8: u = static_cast<std::uint8_t>(static_cast<std::int8_t>(v)); break;
    case PlyType::UInt8: u = static_cast<std::uint8_t>(v); break;
    case PlyType::Int16: u = static_cast<std::uint16_t>(static_cast<std::int16_t>(v)); break;
    case PlyType::UInt16: u = static_cast<std::uint16_t>(v); break;
    case PlyType::Int32: u = static_cast<std::uint32_t>(static_cast<std::int32_t>(v)); break;
    case PlyType::UInt32: u = static_cast<std::uint32_t>(v); break;
    case PlyType::Float32: u = std::bit_cast<std::uint32_t>(static_cast<float>(v)); break;
    case PlyType::Float64: u = std::bit_cast<std::uint64_t>(v); break;
  }
  for (std::size_t i = 0; i < n; ++i) b[big ? n - 1 - i : i] = static_cast<unsigned char>(u >> (8 * i));
  out.append(reinterpret_cast<const char*>(b.data()), n);
}

struct Composer {
  PlyFormat format = PlyFormat::Ascii;
  std::string eol = "\n";          // of the header lines
  bool long_type_names = false;    // int32 instead of int, ...
  std::string header_extra;        // lines added after the format line (comments, obj_info)
};

inline std::string compose_ply(const Composer& c, const std::vector<Elem>& elements) {
  const char* fmt = c.format == PlyFormat::Ascii ? "ascii" : c.format == PlyFormat::BinaryLittleEndian ? "binary_little_endian" : "binary_big_endian";
  std::string out = "ply" + c.eol + "format " + fmt + " 1.0" + c.eol + c.header_extra;
  for (const Elem& e : elements) {
    out += "element " + e.name + " " + std::to_string(e.rows.size()) + c.eol;
    for (const Prop& p : e.props) {
      out += p.list ? std::string("property list ") + type_word(p.count_type, c.long_type_names) + " " + type_word(p.type, c.long_type_names)
                    : std::string("property ") + type_word(p.type, c.long_type_names);
      out += " " + p.name + c.eol;
    }
  }
  out += "end_header" + c.eol;
  const bool big = c.format == PlyFormat::BinaryBigEndian;
  for (const Elem& e : elements)
    for (const auto& row : e.rows) {
      for (std::size_t k = 0; k < e.props.size(); ++k) {
        const Prop& p = e.props[k];
        if (c.format == PlyFormat::Ascii) {
          if (p.list) {
            put_ascii(out, static_cast<double>(row[k].size()), p.count_type);
            out += ' ';
          }
          for (double v : row[k]) {
            put_ascii(out, v, p.type);
            out += ' ';
          }
        } else {
          if (p.list) put_binary(out, static_cast<double>(row[k].size()), p.count_type, big);
          for (double v : row[k]) put_binary(out, v, p.type, big);
        }
      }
      if (c.format == PlyFormat::Ascii) out.back() = '\n';
    }
  return out;
}

// The vertex element of a mesh: x, y, z of `type` among `extra` properties (placed
// before, between and after the coordinates); extra values are small integers, lists
// have two items.
inline Elem vertex_element(const TriangleMesh& m, PlyType type, const std::vector<Prop>& extra = {}) {
  Elem e{"vertex", {}, {}};
  const std::array<std::string, 3> axes{"x", "y", "z"};
  std::vector<int> slot;  // -1 extra, else the axis
  std::size_t next_extra = 0;
  for (int k = 0; k < 3; ++k) {
    if (next_extra < extra.size()) {  // one extra before each coordinate, the rest at the end
      e.props.push_back(extra[next_extra++]);
      slot.push_back(-1);
    }
    e.props.push_back(Prop{axes[static_cast<std::size_t>(k)], type});
    slot.push_back(k);
  }
  for (; next_extra < extra.size(); ++next_extra) {
    e.props.push_back(extra[next_extra]);
    slot.push_back(-1);
  }
  for (const Vec3& v : m.vertices) {
    std::vector<std::vector<double>> row;
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      if (slot[k] >= 0) {
        row.push_back({v[slot[k]]});
      } else {
        row.push_back(e.props[k].list ? std::vector<double>{1, 2} : std::vector<double>{7});
      }
    }
    e.rows.push_back(std::move(row));
  }
  return e;
}

// The face element: the index list `name` with the given count and index types, after
// and before `extra` properties.
inline Elem face_element(const TriangleMesh& m, PlyType count, PlyType index, const std::vector<Prop>& extra = {},
                         const std::string& name = "vertex_indices") {
  Elem e{"face", {}, {}};
  if (!extra.empty()) e.props.push_back(extra.front());
  e.props.push_back(Prop{name, index, true, count});
  for (std::size_t k = 1; k < extra.size(); ++k) e.props.push_back(extra[k]);
  for (const auto& f : m.faces) {
    std::vector<std::vector<double>> row;
    for (const Prop& p : e.props) {
      if (p.name == name) {
        row.push_back({static_cast<double>(f[0]), static_cast<double>(f[1]), static_cast<double>(f[2])});
      } else {
        row.push_back(p.list ? std::vector<double>{0.25, 0.5, 0.75, 1} : std::vector<double>{3});
      }
    }
    e.rows.push_back(std::move(row));
  }
  return e;
}

}  // namespace meshtest
