#include "ply_writer.hpp"

#include <cloth/io/mesh_check.hpp>
#include <cloth/io/number_text.hpp>

#include <ccd/io/atomic_file.hpp>

#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>

namespace ccd::cloth {

namespace {

template <class U>
void append_binary(std::string& out, U u, bool swap) {
  if (swap) {
    if constexpr (sizeof(U) == 4) u = __builtin_bswap32(u);
    if constexpr (sizeof(U) == 8) u = __builtin_bswap64(u);
  }
  std::array<char, sizeof(U)> bytes{};
  std::memcpy(bytes.data(), &u, sizeof(U));
  out.append(bytes.data(), sizeof(U));
}

std::string header(const TriangleMesh& mesh, PlyEncoding e, bool uint_indices) {
  const char* format = e.format == PlyFormat::Ascii ? "ascii" : e.format == PlyFormat::BinaryLittleEndian ? "binary_little_endian" : "binary_big_endian";
  const char* scalar = e.coordinates == PlyScalar::Double ? "double" : "float";
  std::string h = std::string("ply\nformat ") + format + " 1.0\ncomment written by ccdlab\n";
  h += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
  for (const char* axis : {"x", "y", "z"}) h += std::string("property ") + scalar + " " + axis + "\n";
  h += "element face " + std::to_string(mesh.faces.size()) + "\n";
  h += std::string("property list uchar ") + (uint_indices ? "uint" : "int") + " vertex_indices\nend_header\n";
  return h;
}

void append_ascii_body(std::string& out, const TriangleMesh& mesh, bool as_float) {
  for (const Vec3& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      if (as_float) {
        append_number(out, static_cast<float>(v[k]));
      } else {
        append_number(out, v[k]);
      }
      out += k < 2 ? ' ' : '\n';
    }
  }
  for (const auto& f : mesh.faces) {
    out += "3";
    for (std::uint32_t i : f) {
      out += ' ';
      append_number(out, i);
    }
    out += '\n';
  }
}

void append_binary_body(std::string& out, const TriangleMesh& mesh, bool as_float, bool swap) {
  out.reserve(out.size() + mesh.vertices.size() * (as_float ? 12 : 24) + mesh.faces.size() * 13);
  for (const Vec3& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      if (as_float) {
        append_binary(out, std::bit_cast<std::uint32_t>(static_cast<float>(v[k])), swap);
      } else {
        append_binary(out, std::bit_cast<std::uint64_t>(v[k]), swap);
      }
    }
  for (const auto& f : mesh.faces) {
    out += '\3';
    for (std::uint32_t i : f) append_binary(out, i, swap);
  }
}

}  // namespace

std::string format_ply(const TriangleMesh& mesh, PlyEncoding encoding) {
  const bool as_float = encoding.coordinates == PlyScalar::Float;
  check_mesh_for_writing(mesh, as_float, "PLY writer");
  const bool uint_indices = mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  std::string out = header(mesh, encoding, uint_indices);
  if (encoding.format == PlyFormat::Ascii) {
    append_ascii_body(out, mesh, as_float);
  } else {
    const bool big = encoding.format == PlyFormat::BinaryBigEndian;
    append_binary_body(out, mesh, as_float, big == (std::endian::native == std::endian::little));
  }
  return out;
}

void write_ply(const std::string& path, const TriangleMesh& mesh, PlyEncoding encoding) {
  write_file_atomically(path, format_ply(mesh, encoding));
}

}  // namespace ccd::cloth
