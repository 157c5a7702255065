#include <cloth/io/ply_reader.hpp>

#include "mesh_test_support.hpp"

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>

namespace cloth_io_ply_reader_test {

using ccd::InputError;
using ccd::cloth::parse_ply;
using ccd::cloth::ply_type_is_integer;
using namespace meshtest;

namespace {

std::string error_of(const std::string& bytes, const std::string& file = "t1.ply") {
  try {
    parse_ply(bytes, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

constexpr std::array<PlyFormat, 3> kFormats{PlyFormat::Ascii, PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian};
constexpr std::array<PlyType, 8> kAllTypes{PlyType::Int8,  PlyType::UInt8,  PlyType::Int16,   PlyType::UInt16,
                                           PlyType::Int32, PlyType::UInt32, PlyType::Float32, PlyType::Float64};

// The mesh of the reader's tests, in a given encoding: vertex and face elements only.
std::string simple_ply(const TriangleMesh& m, PlyFormat f, PlyType coordinate = PlyType::Float64) {
  Composer c;
  c.format = f;
  return compose_ply(c, {vertex_element(m, coordinate), face_element(m, PlyType::UInt8, PlyType::Int32)});
}

}  // namespace

TEST_CASE("PLY reader: every encoding reads the same mesh bit for bit", "[cloth][io][ply]") {
  const TriangleMesh dyadic = dyadic_mesh();
  std::vector<Prop> every_type;  // one scalar of each type, and lists of each count type
  for (PlyType t : kAllTypes) {
    every_type.push_back({std::string("s_") + type_word(t, false), t});
    if (ply_type_is_integer(t)) every_type.push_back({std::string("l_") + type_word(t, false), PlyType::Float64, true, t});
  }
  const std::vector<std::vector<Prop>> vertex_extras{
      every_type,
      {},
      {{"red", PlyType::UInt8}, {"green", PlyType::UInt8}, {"blue", PlyType::UInt8}, {"alpha", PlyType::UInt8}},
      {{"nx", PlyType::Float32}, {"ny", PlyType::Float32}, {"nz", PlyType::Float32}, {"s", PlyType::Float64}, {"t", PlyType::Float64}},
      {{"flags", PlyType::Int16}, {"uv", PlyType::Float32, true, PlyType::UInt16}, {"id", PlyType::UInt32}, {"w", PlyType::Int8}},
  };
  const std::vector<std::vector<Prop>> face_extras{
      {}, {{"material", PlyType::Int32}, {"texcoord", PlyType::Float32, true, PlyType::UInt8}, {"flags", PlyType::UInt16}}};
  std::size_t variants = 0;
  for (PlyFormat format : kFormats)
    for (PlyType coordinate : {PlyType::Float32, PlyType::Float64})
      for (const auto& vx : vertex_extras)
        for (const auto& fx : face_extras)
          for (PlyType count : {PlyType::UInt8, PlyType::Int8, PlyType::UInt16, PlyType::Int16, PlyType::Int32, PlyType::UInt32})
            for (PlyType index : {PlyType::Int32, PlyType::UInt32, PlyType::UInt16, PlyType::UInt8})
              for (bool long_names : {false, true}) {
                Composer c;
                c.format = format;
                c.long_type_names = long_names;
                const std::string bytes = compose_ply(c, {vertex_element(dyadic, coordinate, vx), face_element(dyadic, count, index, fx)});
                INFO("variant " << variants << ":\n" << bytes.substr(0, bytes.find("end_header")));
                REQUIRE(same_bits(parse_ply(bytes, "t.ply"), dyadic));
                ++variants;
              }
  CHECK(variants == 3 * 2 * 5 * 2 * 6 * 4 * 2);

  SECTION("doubles far from the origin, subnormal, tiny and huge: every format, exactly") {
    const TriangleMesh m = double_mesh();
    for (PlyFormat format : kFormats) CHECK(same_bits(parse_ply(simple_ply(m, format), "t.ply"), m));
  }
  SECTION("float coordinates are the floats, widened") {
    const TriangleMesh m = double_mesh();
    // double_mesh has values beyond the float range: keep the first three vertices.
    TriangleMesh small = m;
    small.vertices.resize(3);
    small.faces = {{0, 1, 2}};
    for (PlyFormat format : kFormats) CHECK(same_bits(parse_ply(simple_ply(small, format, PlyType::Float32), "t.ply"), as_floats(small)));
  }
  SECTION("integer coordinates give their values") {
    TriangleMesh m;
    m.vertices = {Vec3(-100, 0, 100), Vec3(1, 2, 3), Vec3(120, -128, 127)};
    m.faces = {{0, 1, 2}};
    for (PlyFormat format : kFormats)
      for (PlyType t : {PlyType::Int8, PlyType::Int16, PlyType::Int32})
        CHECK(same_bits(parse_ply(simple_ply(m, format, t), "t.ply"), m));
  }
}

TEST_CASE("PLY reader: headers, other elements, line ends", "[cloth][io][ply]") {
  const TriangleMesh m = dyadic_mesh();
  const Elem edges{"edge",
                   {{"vertex1", PlyType::Int32}, {"vertex2", PlyType::Int32}, {"crease", PlyType::UInt8}},
                   {{{0}, {1}, {255}}, {{1}, {2}, {0}}}};
  const Elem material{"material", {{"name", PlyType::UInt8, true, PlyType::UInt8}, {"shine", PlyType::Float64}}, {{{65, 66, 67}, {0.5}}}};
  const Elem nothing{"empty", {}, {}};
  for (PlyFormat format : kFormats) {
    Composer c;
    c.format = format;
    SECTION("elements before, between and after") {
      const std::string bytes = compose_ply(c, {edges, vertex_element(m, PlyType::Float32), material,
                                                face_element(m, PlyType::UInt8, PlyType::Int32), edges, nothing});
      CHECK(same_bits(parse_ply(bytes, "t.ply"), m));
    }
    SECTION("faces before vertices, and the index list named vertex_index") {
      const std::string bytes = compose_ply(c, {face_element(m, PlyType::UInt8, PlyType::UInt32, {}, "vertex_index"), vertex_element(m, PlyType::Float64)});
      CHECK(same_bits(parse_ply(bytes, "t.ply"), m));
    }
    SECTION("CRLF header lines, comments and obj_info") {
      c.eol = "\r\n";
      c.header_extra = "comment made by hand\r\nobj_info frame 12\r\n\r\ncomment\r\n";
      std::string bytes = compose_ply(c, {vertex_element(m, PlyType::Float64), face_element(m, PlyType::UInt8, PlyType::Int32)});
      if (format == PlyFormat::Ascii) {  // CRLF in the body too
        const std::size_t body = bytes.find("end_header\r\n") + 12;
        std::string crlf;
        for (char ch : bytes.substr(body)) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
        bytes = bytes.substr(0, body) + crlf;
      }
      CHECK(same_bits(parse_ply(bytes, "t.ply"), m));
    }
  }
  SECTION("ascii: tabs, a leading '+', blank lines and a missing last line end") {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "\t+1 2.5e0 -0\n\n  0 1 0  \n0 0 1\n3 0\t1 2";
    const TriangleMesh r = parse_ply(text, "t.ply");
    REQUIRE(r.vertices.size() == 3);
    CHECK(r.vertices[0] == Vec3(1, 2.5, 0));
    CHECK(std::signbit(r.vertices[0].z()));
    CHECK(r.faces == std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}});
  }
  SECTION("zero vertices and zero faces") {
    const TriangleMesh empty;
    for (PlyFormat format : kFormats) {
      const TriangleMesh r = parse_ply(simple_ply(empty, format), "t.ply");
      CHECK(r.vertices.empty());
      CHECK(r.faces.empty());
    }
  }
}

TEST_CASE("PLY reader: bad input is one line naming the file, the element and its index", "[cloth][io][ply]") {
  const TriangleMesh m = dyadic_mesh();  // 7 vertices, 5 faces
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
  SECTION("files that are not PLY or whose header is broken") {
    CHECK(error_of("") == "t1.ply: empty file");
    CHECK(error_of("solid cube\n") == "t1.ply: not a PLY file (the first line is not 'ply')");
    CHECK(error_of("ply") == "t1.ply: not a PLY file (the first line is not 'ply')");
    CHECK(error_of("ply\n") == "t1.ply: header: no end_header line (the file ends in the header)");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 3\n") == "t1.ply: header: no end_header line (the file ends in the header)");
    CHECK(error_of("ply\nend_header\n") == "t1.ply: header: no format line");
    CHECK(error_of("ply\nformat ascii 1.0\nend_header\n") == "t1.ply: header: no vertex element");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n") ==
          "t1.ply: header: no face element");
    CHECK(error_of("ply\nformat binary_middle_endian 1.0\nend_header\n") ==
          "t1.ply: header line 2: unknown format 'binary_middle_endian' (ascii, binary_little_endian or binary_big_endian)");
    CHECK(error_of("ply\nformat ascii 2.0\nend_header\n") == "t1.ply: header line 2: unsupported format version '2.0' (1.0 is read)");
    CHECK(error_of("ply\nformat ascii 1.0\nformat ascii 1.0\n") == "t1.ply: header line 3: a second format line");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty half x\n") ==
          "t1.ply: header line 4: unknown type 'half' (char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
    CHECK(error_of("ply\nformat ascii 1.0\nproperty float x\n") == "t1.ply: header line 3: property before any element");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex -3\n") ==
          "t1.ply: header line 3: element 'vertex': count '-3' is not an integer from 0 to 2^64 - 1");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n") ==
          "t1.ply: header line 3: element 'vertex': count '99999999999999999999999' is not an integer from 0 to 2^64 - 1");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty double x\n") ==
          "t1.ply: header line 5: property 'x' appears twice in element 'vertex'");
    CHECK(error_of("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n") ==
          "t1.ply: header line 4: list 'vertex_indices': the count type 'float' is not an integer type");
    CHECK(error_of("ply\nformat ascii 1.0\nvertices 3\n") ==
          "t1.ply: header line 3: unknown keyword 'vertices' (format, element, property, comment, obj_info, end_header)");
    CHECK(error_of("ply\nformat ascii 1.0\nelement v\x01rtex 3\n") == "t1.ply: header line 3: a byte that is not printable ASCII in a header line");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n") ==
          "t1.ply: header: the vertex element has no property 'z'");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 0\nproperty list uchar float vertex_indices\nend_header\n") ==
          "t1.ply: header: face property 'vertex_indices': the index type float is not an integer type");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 0\nproperty int vertex_indices\nend_header\n") ==
          "t1.ply: header: face property 'vertex_indices' is not a list");
  }
  SECTION("counts beyond the file are refused before anything is allocated") {
    CHECK(error_of("ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n0123456789") ==
          "t1.ply: element vertex: the header declares 1000000000000, of at least 12 bytes each, but only 10 bytes of the file "
          "are left for them (truncated or corrupt file)");
    CHECK(error_of("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 18446744073709551615\nproperty list uchar int vertex_indices\nend_header\n"
                   "0 0 0\n1 1 1\n") ==
          "t1.ply: element face: the header declares 18446744073709551615, of at least 8 bytes each, but only 1 bytes of the "
          "file are left for them (truncated or corrupt file)");
  }
  SECTION("bodies that end early name the element and index where they ran out") {
    // Without lists of any length on the way, the smallest size of every element is its
    // size: a cut binary body fails the count check.
    std::string binary = simple_ply(m, PlyFormat::BinaryLittleEndian);
    const std::size_t body = binary.find("end_header\n") + 11;
    CHECK(error_of(binary.substr(0, body + 24 * 7 + 13 * 4)) ==
          "t1.ply: element face: the header declares 5, of at least 13 bytes each, but only 52 bytes of the file are left "
          "for them (truncated or corrupt file)");
    // With a vertex list of any length, the fewest bytes are not known in advance.
    Composer c;
    c.format = PlyFormat::BinaryBigEndian;
    const std::string listed = compose_ply(c, {vertex_element(m, PlyType::Float64, {{"uv", PlyType::Float64, true, PlyType::UInt8}}),
                                               face_element(m, PlyType::UInt8, PlyType::Int32)});
    CHECK(error_of(listed.substr(0, listed.size() - 5 * 13 - 20)) == "t1.ply: vertex 6: the file ends inside this vertex (truncated body)");
    CHECK(error_of(binary.substr(0, binary.size() - 2)) ==
          "t1.ply: element face: the header declares 5, of at least 13 bytes each, but only 63 bytes of the file are left "
          "for them (truncated or corrupt file)");
    // Ascii: the count check takes two bytes per value; lines padded with spaces pass it.
    CHECK(error_of(head + "0 0 0\n1 0 0\n") ==
          "t1.ply: element vertex: the header declares 3, of at least 6 bytes each, but only 13 bytes of the file are left "
          "for them (truncated or corrupt file)");
    CHECK(error_of(head + "0 0 0                  \n1 0 0              \n") ==
          "t1.ply: vertex 2: the file ends before this vertex (truncated body: the header declares 3)");
    CHECK(error_of(head + verts + "3 0 1      ") == "t1.ply: face 0: the line ends before property 'vertex_indices'");
    CHECK(error_of(head + "0 0 0\n1 0     \n0 1 0\n3 0 1 2\n") == "t1.ply: vertex 1: the line ends before property 'z'");
  }
  SECTION("negative list counts") {
    const std::string text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                             "property list char float uv\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0 0\n1 0 0 0\n0 1 0 1 0.5\n0 0 1 -2 0.5 0.5\n";
    CHECK(error_of(text) == "t1.ply: vertex 3: list 'uv' has a negative count -2");
    Composer c;
    c.format = PlyFormat::BinaryLittleEndian;
    std::string bytes = compose_ply(c, {vertex_element(m, PlyType::Float32, {{"uv", PlyType::Float32, true, PlyType::Int16}}),
                                        face_element(m, PlyType::UInt8, PlyType::Int32)});
    // vertex 0: uv (2 + 8 bytes), x, y, z (12 bytes): its count is the first two bytes of the body
    const std::size_t body = bytes.find("end_header\n") + 11;
    bytes[body + 1] = '\x80';
    CHECK(error_of(bytes) == "t1.ply: vertex 0: list 'uv' has a negative count -32766");
  }
  SECTION("bytes or text after the last element") {
    CHECK(error_of(head + verts + "3 0 1 2\n\n0 0 0\n") == "t1.ply: line 15: text after the last element: '0'");
    CHECK(error_of(head + verts + "3 0 1 2 7\n") == "t1.ply: face 0: extra value '7' at the end of the line (line 13)");
    CHECK(error_of(simple_ply(m, PlyFormat::BinaryLittleEndian) + "\n") ==
          "t1.ply: 1 bytes after the last element (the header declares fewer elements than the file holds)");
  }
  SECTION("values that are not numbers of their type") {
    CHECK(error_of(head + "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n") == "t1.ply: vertex 1: z is not a number of type float: 'zero'");
    CHECK(error_of(head + "0 0 0\n1 0 1e39\n0 1 0\n3 0 1 2\n") == "t1.ply: vertex 1: z '1e39' is out of the range of float");
    CHECK(error_of(head + "0 0 0\n1 0 0x1p3\n0 1 0\n3 0 1 2\n") == "t1.ply: vertex 1: z is not a number of type float: '0x1p3'");
    CHECK(error_of(head + verts + "3.0 0 1 2\n") == "t1.ply: face 0: vertex_indices is not a number of type uchar: '3.0'");
    CHECK(error_of(head + verts + "256 0 1 2\n") == "t1.ply: face 0: vertex_indices '256' is out of the range of uchar");
  }
  SECTION("NaN and infinite coordinates") {
    CHECK(error_of(head + "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n") == "t1.ply: vertex 1: z is NaN");
    CHECK(error_of(head + "0 -inf 0\n1 0 0\n0 1 0\n3 0 1 2\n") == "t1.ply: vertex 0: y is infinite");
    TriangleMesh bad = m;
    bad.vertices[5].x() = std::numeric_limits<double>::quiet_NaN();
    for (PlyFormat f : {PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian}) {
      CHECK(error_of(simple_ply(bad, f)) == "t1.ply: vertex 5: x is NaN");
      CHECK(error_of(simple_ply(bad, f, PlyType::Float32)) == "t1.ply: vertex 5: x is NaN");
    }
    bad.vertices[5].x() = 1;
    bad.vertices[6].y() = -std::numeric_limits<double>::infinity();
    CHECK(error_of(simple_ply(bad, PlyFormat::BinaryBigEndian)) == "t1.ply: vertex 6: y is infinite");
  }
  SECTION("faces that are not triangles, indices out of range") {
    CHECK(error_of(head + verts + "4 0 1 2 0\n") == "t1.ply: face 0: has 4 vertices; only triangles are read");
    TriangleMesh bad = m;
    bad.faces[3] = {6, 7, 0};
    CHECK(error_of(simple_ply(bad, PlyFormat::BinaryLittleEndian)) == "t1.ply: face 3: vertex index 7 out of range (the file has 7 vertices)");
    CHECK(error_of(simple_ply(bad, PlyFormat::Ascii)) == "t1.ply: face 3: vertex index 7 out of range (the file has 7 vertices)");
    CHECK(error_of(head + verts + "3 0 -1 2\n") == "t1.ply: face 0: vertex index -1 is negative");
    Composer c;
    c.format = PlyFormat::BinaryBigEndian;
    std::string bytes = compose_ply(c, {vertex_element(m, PlyType::Float32), face_element(m, PlyType::UInt8, PlyType::Int32)});
    bytes[bytes.size() - 13 * 3] = 4;  // face 2's count
    CHECK(error_of(bytes) == "t1.ply: face 2: has 4 vertices; only triangles are read");
    bytes[bytes.size() - 13 * 3] = 3;
    bytes[bytes.size() - 13 * 3 + 1] = '\xff';  // face 2's first index: negative
    CHECK(error_of(bytes).starts_with("t1.ply: face 2: vertex index -"));
  }
}

}  // namespace cloth_io_ply_reader_test
