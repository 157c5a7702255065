#include <cloth/io/mesh_file.hpp>

#include <cloth/io/obj_writer.hpp>
#include <cloth/io/ply_writer.hpp>

#include "mesh_test_support.hpp"

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cloth_io_mesh_file_test {

using ccd::InputError;
using ccd::cloth::MeshFrames;
using ccd::cloth::PlyEncoding;
using ccd::cloth::PlyScalar;
using ccd::cloth::read_mesh;
using ccd::cloth::read_mesh_frames;
using namespace meshtest;
namespace fs = std::filesystem;

namespace {

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("ccdlab-mesh-file-" + std::to_string(::getpid()))) { fs::create_directories(path_); }
  ~TempDir() { fs::remove_all(path_); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

void put(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("mesh files: PLY or OBJ by content, then by name", "[cloth][io]") {
  const TempDir dir;
  const TriangleMesh m = double_mesh();
  ccd::cloth::write_ply(dir / "a.ply", m, {PlyFormat::Ascii, PlyScalar::Double});
  ccd::cloth::write_ply(dir / "b.data", m, {PlyFormat::BinaryBigEndian, PlyScalar::Double});  // PLY by content
  ccd::cloth::write_obj(dir / "c.obj", m);
  ccd::cloth::write_obj(dir / "d.txt", m);  // OBJ: not PLY by content or name
  for (const char* name : {"a.ply", "b.data", "c.obj", "d.txt"}) {
    INFO(name);
    CHECK(same_bits(read_mesh(dir / name), m));
  }
  put(dir / "e.PLY", "v 0 0 0\n");
  CHECK(error_of([&] { read_mesh(dir / "e.PLY"); }) == dir / "e.PLY" + ": not a PLY file (the first line is not 'ply')");
  put(dir / "empty.obj", "");
  CHECK(error_of([&] { read_mesh(dir / "empty.obj"); }) == dir / "empty.obj" + ": empty file");
  CHECK(error_of([&] { read_mesh(dir / "missing.ply"); }) == dir / "missing.ply" + ": cannot open the file: No such file or directory");
  fs::create_directories(dir / "folder.ply");
  CHECK(error_of([&] { read_mesh(dir / "folder.ply"); }) == dir / "folder.ply" + ": is a folder, not a mesh file");
  CHECK(error_of([] { read_mesh("/dev/zero"); }) ==
        "/dev/zero: is not a regular file (a device or a pipe); mesh frames are read from regular files");
}

TEST_CASE("mesh frames: two frames of one mesh", "[cloth][io]") {
  const TempDir dir;
  TriangleMesh t0 = dyadic_mesh();
  TriangleMesh t1 = t0;
  for (Vec3& v : t1.vertices) v += Vec3(0.25, -0.5, 1);
  ccd::cloth::write_ply(dir / "t0.ply", t0);
  ccd::cloth::write_obj(dir / "t1.obj", t1);
  for (unsigned threads : {1u, 2u}) {
    const MeshFrames frames = read_mesh_frames(dir / "t0.ply", dir / "t1.obj", threads);
    CHECK(same_bits(TriangleMesh{frames.vertices0, frames.faces}, t0));
    CHECK(same_bits(TriangleMesh{frames.vertices1, frames.faces}, t1));
  }

  TriangleMesh other = t1;
  other.faces[3] = {6, 5, 3};
  ccd::cloth::write_ply(dir / "t1.ply", other);
  CHECK(error_of([&] { read_mesh_frames(dir / "t0.ply", dir / "t1.ply"); }) ==
        dir / "t1.ply" + ": face 3: (6, 5, 3) differs from " + dir / "t0.ply" + "'s face 3 (6, 5, 4)");
  other.faces = t1.faces;
  other.faces.pop_back();
  ccd::cloth::write_ply(dir / "t1.ply", other);
  CHECK(error_of([&] { read_mesh_frames(dir / "t0.ply", dir / "t1.ply"); }) ==
        dir / "t1.ply" + ": has 4 faces, " + dir / "t0.ply" + " has 5 (frames of one mesh have the same faces)");
  other = t1;
  other.vertices.emplace_back(0, 0, 0);
  ccd::cloth::write_ply(dir / "t1.ply", other);
  CHECK(error_of([&] { read_mesh_frames(dir / "t0.ply", dir / "t1.ply"); }) ==
        dir / "t1.ply" + ": has 8 vertices, " + dir / "t0.ply" + " has 7 (frames of one mesh have the same vertices)");
  // The first frame's errors come first, whatever the threads.
  put(dir / "bad.ply", "ply\n");
  for (unsigned threads : {1u, 2u}) {
    CHECK(error_of([&] { read_mesh_frames(dir / "bad.ply", dir / "missing.obj", threads); }) ==
          dir / "bad.ply" + ": header: no end_header line (the file ends in the header)");
    CHECK(error_of([&] { read_mesh_frames(dir / "t0.ply", dir / "bad.ply", threads); }) ==
          dir / "bad.ply" + ": header: no end_header line (the file ends in the header)");
  }
}

TEST_CASE("mesh files: the fixtures of data/meshes read the same tetrahedron", "[cloth][io]") {
  // data/meshes: as Blender writes ascii PLY (CRLF, normals, uv, colours, uint indices), as a
  // simulator writes binary PLY (doubles, velocities, an edge element after the faces), as
  // a modelling program writes OBJ (v/vt/vn, v//vn with negative indices, v).
  TriangleMesh tetrahedron;
  tetrahedron.vertices = {Vec3(0, 0, 0), Vec3(1.5, 0, 0), Vec3(0, 0.25, 0), Vec3(0, 0, -2.125)};
  tetrahedron.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const char* name : {"tetrahedron-blender.ply", "tetrahedron-simulator.ply", "tetrahedron.obj"}) {
    INFO(name);
    CHECK(same_bits(read_mesh(std::string(CCDLAB_SOURCE_DIR) + "/data/meshes/" + name), tetrahedron));
  }
}

}  // namespace cloth_io_mesh_file_test
