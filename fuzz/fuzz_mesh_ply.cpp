// The PLY mesh reader (cloth/io/ply_reader.hpp): any bytes either give InputError or a
// mesh whose indices are in range and whose coordinates are finite, and which every
// encoding of the writer (ascii, both byte orders, doubles) reads back bit for bit.
#include "fuzz_support.hpp"

#include <cloth/io/ply_reader.hpp>
#include <cloth/io/ply_writer.hpp>

#include <ccd/io/input_error.hpp>

#include <bit>
#include <cmath>

namespace {

bool same_bits(const ccd::cloth::TriangleMesh& a, const ccd::cloth::TriangleMesh& b) {
  if (a.vertices.size() != b.vertices.size() || a.faces != b.faces) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (std::bit_cast<std::uint64_t>(a.vertices[i][k]) != std::bit_cast<std::uint64_t>(b.vertices[i][k])) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccd::cloth::TriangleMesh mesh;
  try {
    mesh = ccd::cloth::parse_ply(ccdfuzz::as_text(data, size), "fuzz.ply");
  } catch (const ccd::InputError&) {
    return 0;
  }
  for (const auto& v : mesh.vertices) FUZZ_CHECK(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()));
  for (const auto& f : mesh.faces)
    for (std::uint32_t i : f) FUZZ_CHECK(i < mesh.vertices.size());
  using ccd::cloth::PlyFormat;
  for (PlyFormat format : {PlyFormat::Ascii, PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian}) {
    const std::string again = ccd::cloth::format_ply(mesh, {format, ccd::cloth::PlyScalar::Double});
    FUZZ_CHECK(same_bits(ccd::cloth::parse_ply(again, "again.ply"), mesh));
  }
  return 0;
}
