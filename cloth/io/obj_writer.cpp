#include "obj_writer.hpp"

#include <cloth/io/mesh_check.hpp>
#include <cloth/io/number_text.hpp>

#include <ccd/io/atomic_file.hpp>

#include <array>
#include <charconv>

namespace ccd::cloth {

std::string format_obj(const TriangleMesh& mesh) {
  check_mesh_for_writing(mesh, false, "OBJ writer");
  std::string out = "# written by ccdlab\n";
  for (const Vec3& v : mesh.vertices) {
    out += 'v';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, v[k]);
    }
    out += '\n';
  }
  for (const auto& f : mesh.faces) {
    out += 'f';
    for (std::uint32_t i : f) {
      out += ' ';
      append_number(out, std::uint64_t{i} + 1);
    }
    out += '\n';
  }
  return out;
}

void write_obj(const std::string& path, const TriangleMesh& mesh) { write_file_atomically(path, format_obj(mesh)); }

}  // namespace ccd::cloth
