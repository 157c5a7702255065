// The OBJ mesh reader (cloth/io/obj_reader.hpp): any bytes either give InputError or a
// mesh whose indices are in range and whose coordinates are finite, and which the OBJ
// writer writes so that it reads back bit for bit.
#include "fuzz_support.hpp"

#include <cloth/io/obj_reader.hpp>
#include <cloth/io/obj_writer.hpp>

#include <ccd/io/input_error.hpp>

#include <bit>
#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccd::cloth::TriangleMesh mesh;
  try {
    mesh = ccd::cloth::parse_obj(ccdfuzz::as_text(data, size), "fuzz.obj");
  } catch (const ccd::InputError&) {
    return 0;
  }
  FUZZ_CHECK(!mesh.vertices.empty());
  for (const auto& v : mesh.vertices) FUZZ_CHECK(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()));
  for (const auto& f : mesh.faces)
    for (std::uint32_t i : f) FUZZ_CHECK(i < mesh.vertices.size());
  const ccd::cloth::TriangleMesh again = ccd::cloth::parse_obj(ccd::cloth::format_obj(mesh), "again.obj");
  FUZZ_CHECK(again.faces == mesh.faces && again.vertices.size() == mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      FUZZ_CHECK(std::bit_cast<std::uint64_t>(again.vertices[i][k]) == std::bit_cast<std::uint64_t>(mesh.vertices[i][k]));
  return 0;
}
