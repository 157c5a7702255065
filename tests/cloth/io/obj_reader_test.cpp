#include <cloth/io/obj_reader.hpp>

#include "mesh_test_support.hpp"

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>

namespace cloth_io_obj_reader_test {

using ccd::InputError;
using ccd::cloth::parse_obj;
using namespace meshtest;

namespace {

std::string error_of(const std::string& text, const std::string& file = "frame.obj") {
  try {
    parse_obj(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string shortest(double v) {
  std::array<char, 32> buf{};
  return std::string(buf.data(), std::to_chars(buf.data(), buf.data() + buf.size(), v).ptr);
}

// The OBJ text of a mesh, each face corner written by `corner` (1-based vertex index,
// face number, corner number), each vertex line followed by `after_vertex`.
template <class Corner>
std::string obj_text(const TriangleMesh& m, Corner corner, const std::string& after_vertex = "", const std::string& eol = "\n") {
  // Appends only: GCC 12 warns falsely (-Wstringop-overflow) on "literal" + temporary.
  std::string s;
  for (const char* line : {"# a test mesh", "mtllib test.mtl", "o mesh"}) (s += line) += eol;
  for (const Vec3& v : m.vertices) {
    s += "v";
    for (int k = 0; k < 3; ++k) (s += ' ') += shortest(v[k]);
    (s += after_vertex) += eol;
  }
  for (const char* line : {"vt 0 0", "vt 1 0", "vn 0 0 1", "g part", "usemtl red", "s off"}) (s += line) += eol;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    s += "f";
    for (std::size_t k = 0; k < 3; ++k) (s += ' ') += corner(static_cast<long>(m.faces[f][k]) + 1, f, k);
    s += eol;
  }
  return s;
}

}  // namespace

TEST_CASE("OBJ reader: every face syntax reads the same mesh bit for bit", "[cloth][io][obj]") {
  const long n = static_cast<long>(double_mesh().vertices.size());
  for (const TriangleMesh& m : {dyadic_mesh(), double_mesh()}) {
    const long count = static_cast<long>(m.vertices.size());
    CHECK(same_bits(parse_obj(obj_text(m, [](long v, auto, auto) { return std::to_string(v); }), "m.obj"), m));
    CHECK(same_bits(parse_obj(obj_text(m, [](long v, auto, auto) { return std::to_string(v) + "/1"; }), "m.obj"), m));
    CHECK(same_bits(parse_obj(obj_text(m, [](long v, auto, auto) { return std::to_string(v) + "//1"; }), "m.obj"), m));
    CHECK(same_bits(parse_obj(obj_text(m, [](long v, auto, auto) { return std::to_string(v) + "/2/1"; }), "m.obj"), m));
    // Negative: relative to the vertices so far (all of them: the faces follow the vertices).
    CHECK(same_bits(parse_obj(obj_text(m, [count](long v, auto, auto) { return std::to_string(v - count - 1) + "/-1/-1"; }), "m.obj"), m));
    // Mixed in one face, vertex colours and weights, CRLF.
    const auto mixed = [](long v, std::size_t, std::size_t k) { return k == 0 ? std::to_string(v) : k == 1 ? std::to_string(v) + "//1" : std::to_string(v) + "/1/1"; };
    CHECK(same_bits(parse_obj(obj_text(m, mixed, " 0.5 0.25 1"), "m.obj"), m));
    CHECK(same_bits(parse_obj(obj_text(m, mixed, " 1.0", "\r\n"), "m.obj"), m));
  }
  CHECK(n == 5);

  SECTION("comments, blank lines, continuations, faces before their vertices") {
    const std::string text =
        "# header\n\n   \nv 1 2 3 # trailing comment\nv 4 \\\n 5 \\\n 6\n\tv +7 8e0 -9\nf 1 2 \\\n 3\nf 3 2 4\nv 0 0 0\n";
    const TriangleMesh r = parse_obj(text, "m.obj");
    REQUIRE(r.vertices.size() == 4);
    CHECK(r.vertices[1] == Vec3(4, 5, 6));
    CHECK(r.vertices[2] == Vec3(7, 8, -9));
    CHECK(r.faces == std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {2, 1, 3}});
  }
  SECTION("a vertex-only file is a mesh without faces") {
    const TriangleMesh r = parse_obj("v 0 0 0\nv 1 1 1\np 1 2\nl 1 2\n", "m.obj");
    CHECK(r.vertices.size() == 2);
    CHECK(r.faces.empty());
  }
}

TEST_CASE("OBJ reader: bad input is one line naming the file and the line", "[cloth][io][obj]") {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
  CHECK(error_of("") == "frame.obj: empty file");
  CHECK(error_of("# nothing\n\n") == "frame.obj: no vertex ('v' line): not an OBJ mesh");
  CHECK(error_of(tri + "f 1 2 3 4\n") == "frame.obj: line 5: face has 4 vertices; only triangles are read");
  CHECK(error_of(tri + "f 1/1 2/1\n") == "frame.obj: line 5: face has 2 vertices; only triangles are read");
  CHECK(error_of(tri + "f 1 2 5\n") == "frame.obj: line 5: vertex index 5 out of range (the file has 4 vertices)");
  CHECK(error_of(tri + "f 1 2 9\nv 0 0 1\n") == "frame.obj: line 5: vertex index 9 out of range (the file has 5 vertices)");
  CHECK(error_of(tri + "f 1 2 -5\n") == "frame.obj: line 5: vertex index -5 out of range (4 vertices before this line)");
  CHECK(error_of(tri + "f 1 0 2\n") ==
        "frame.obj: line 5: vertex index 0 (OBJ indices start at 1; negative ones count back from the last vertex)");
  CHECK(error_of(tri + "f 1 2 3x\n") == "frame.obj: line 5: face corner '3x' is not v, v/vt, v//vn or v/vt/vn with integer indices");
  CHECK(error_of(tri + "f 1 2 3/a\n") == "frame.obj: line 5: face corner '3/a' is not v, v/vt, v//vn or v/vt/vn with integer indices");
  CHECK(error_of(tri + "f 1 2 3/\n") == "frame.obj: line 5: face corner '3/' is not v, v/vt, v//vn or v/vt/vn with integer indices");
  CHECK(error_of(tri + "f 1 2 99999999999\n") == "frame.obj: line 5: vertex index 99999999999 out of range (more than 4294967295)");
  CHECK(error_of("v 0 0\n") == "frame.obj: line 1: a vertex has 2 numbers; expected x y z, x y z w or x y z r g b");
  CHECK(error_of("v 0 0 0 1 1\n") == "frame.obj: line 1: a vertex has 5 numbers; expected x y z, x y z w or x y z r g b");
  CHECK(error_of("v 0 0 0 1 1 1 1 1\n") == "frame.obj: line 1: a vertex has more than 7 numbers (x y z, x y z w or x y z r g b)");
  CHECK(error_of("v 0 0 zero\n") == "frame.obj: line 1: z is not a number: 'zero'");
  CHECK(error_of("v 0 1e999 0\n") == "frame.obj: line 1: y '1e999' is beyond the range of a double");
  CHECK(error_of("v 0 0 0 abc\n") == "frame.obj: line 1: value 4 is not a number: 'abc'");
  CHECK(error_of("\n\nv 0 0 nan\n") == "frame.obj: line 3: z is NaN");
  CHECK(error_of("v -inf 0 0\n") == "frame.obj: line 1: x is infinite");
  CHECK(error_of("v 0 0 0\nvertex 1 2 3\n") == "frame.obj: line 2: unknown statement 'vertex'");
  CHECK(error_of("v 0 0 0\n\x7f\x45LF\x01\n") == "frame.obj: line 2: unknown statement '?ELF?'");
  CHECK(error_of("v 0 \\\n0 \\\n0\nf 1 1 1 1\n") == "frame.obj: line 4: face has 4 vertices; only triangles are read");
}

}  // namespace cloth_io_obj_reader_test
