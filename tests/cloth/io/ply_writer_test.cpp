#include <cloth/io/ply_writer.hpp>

#include <cloth/io/ply_reader.hpp>

#include "mesh_test_support.hpp"

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace cloth_io_ply_writer_test {

using ccd::cloth::format_ply;
using ccd::cloth::parse_ply;
using ccd::cloth::PlyEncoding;
using ccd::cloth::PlyScalar;
using ccd::cloth::read_ply;
using ccd::cloth::write_ply;
using namespace meshtest;

TEST_CASE("PLY writer: every encoding reads back bit for bit", "[cloth][io][ply]") {
  const TriangleMesh doubles = double_mesh();
  TriangleMesh in_float_range = doubles;  // without the values beyond the float range
  in_float_range.vertices.resize(3);
  in_float_range.faces = {{0, 1, 2}, {2, 1, 0}};
  for (PlyFormat f : {PlyFormat::Ascii, PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian}) {
    INFO("format " << static_cast<int>(f));
    CHECK(same_bits(parse_ply(format_ply(doubles, {f, PlyScalar::Double}), "w.ply"), doubles));
    CHECK(same_bits(parse_ply(format_ply(dyadic_mesh(), {f, PlyScalar::Float}), "w.ply"), dyadic_mesh()));
    // Floats are the nearest floats: not the doubles, and exactly the floats.
    const TriangleMesh rounded = parse_ply(format_ply(in_float_range, {f, PlyScalar::Float}), "w.ply");
    CHECK(same_bits(rounded, as_floats(in_float_range)));
    CHECK_FALSE(same_bits(rounded, in_float_range));
  }
  SECTION("the default is binary little-endian doubles, with the header the readers expect") {
    const std::string bytes = format_ply(dyadic_mesh());
    CHECK(bytes.starts_with("ply\nformat binary_little_endian 1.0\ncomment written by ccdlab\nelement vertex 7\n"
                            "property double x\nproperty double y\nproperty double z\nelement face 5\n"
                            "property list uchar int vertex_indices\nend_header\n"));
    CHECK(bytes.size() == bytes.find("end_header\n") + 11 + 7 * 24 + 5 * 13);
  }
  SECTION("ascii doubles are the shortest round-trip decimals") {
    TriangleMesh m;
    m.vertices = {Vec3(0.1, -0.0, 1e-300), Vec3(1048576.0000000009313, 5e-324, 1.0 / 3.0), Vec3(2, 3, 4)};
    m.faces = {{0, 1, 2}};
    const std::string text = format_ply(m, {PlyFormat::Ascii, PlyScalar::Double});
    CHECK(text.substr(text.find("end_header\n") + 11) ==
          "0.1 -0 1e-300\n1048576.000000001 5e-324 0.3333333333333333\n2 3 4\n3 0 1 2\n");
  }
  SECTION("meshes that would not read back are refused") {
    TriangleMesh bad = dyadic_mesh();
    bad.faces[2][1] = 7;
    CHECK_THROWS_WITH(format_ply(bad), "PLY writer: face 2: vertex index 7 out of range (7 vertices)");
    bad = dyadic_mesh();
    bad.vertices[4].z() = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(format_ply(bad), "PLY writer: vertex 4: z is NaN");
    bad = dyadic_mesh();
    bad.vertices[1].y() = 1e39;
    CHECK_NOTHROW(format_ply(bad));
    CHECK_THROWS_WITH(format_ply(bad, {PlyFormat::Ascii, PlyScalar::Float}), "PLY writer: vertex 1: y is beyond the float range");
    bad.vertices[1].y() = -std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(format_ply(bad), "PLY writer: vertex 1: y is infinite");
  }
}

TEST_CASE("PLY writer: files are written whole, in place of the old one", "[cloth][io][ply]") {
  const auto dir = std::filesystem::temp_directory_path() / ("ccdlab-ply-writer-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "frame.ply").string();
  write_ply(path, dyadic_mesh(), {PlyFormat::BinaryBigEndian, PlyScalar::Float});
  CHECK(same_bits(read_ply(path), dyadic_mesh()));
  write_ply(path, double_mesh());
  CHECK(same_bits(read_ply(path), double_mesh()));
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);  // no temporary left
  CHECK_THROWS_AS(write_ply((dir / "no-such-folder" / "f.ply").string(), dyadic_mesh()), ccd::InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace cloth_io_ply_writer_test
