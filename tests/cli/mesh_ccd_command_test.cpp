// `ccdlab ccd FRAME0 FRAME1` and `ccdlab mesh-frames`: the output's fields, the same
// collisions as the library call on the same frames (the PLY files carry the doubles
// exactly), --exact, thread counts, and bad input (exit 2, one line, nothing written).
#include "cli_support.hpp"

#include <cloth/mesh_ccd/mesh_ccd.hpp>
#include <cloth/mesh_ccd/mesh_frames.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace cli_mesh_ccd_command_test {

namespace fs = std::filesystem;
using nlohmann::json;
using ccdlab::test::Folder;

namespace {

int run(const std::string& args, const Folder& dir, std::string* out = nullptr, std::string* err = nullptr) {
  return ccdlab::test::run_ccdlab(args, dir, out, err);
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// An ascii PLY file of the given vertices (text as written) and faces.
void write_ply(const std::string& path, const std::vector<std::string>& vertices,
               const std::vector<std::string>& faces) {
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex " << vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << faces.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& v : vertices) out << v << "\n";
  for (const auto& f : faces) out << f << "\n";
}

json without_timing(json j) {
  j.erase("seconds");
  j.erase("peak_memory_bytes");
  j["options"].erase("threads");
  return j;
}

}  // namespace

TEST_CASE("ccdlab ccd FRAME0 FRAME1 writes ccdlab-mesh-ccd/1 with the library's collisions", "[cloth][cli][mesh_ccd]") {
  Folder dir;
  REQUIRE(run("mesh-frames crumpled --faces 400 --seed 3 -o " + (dir / "f"), dir) == 0);
  const std::string f0 = dir / "f/frame0.ply", f1 = dir / "f/frame1.ply";
  std::string out;
  REQUIRE(run("ccd " + f0 + " " + f1 + " --separation 0.001 --quiet -o " + (dir / "r.json"), dir, &out) == 0);
  CHECK(out.find("collisions (conservative kernel): ") != std::string::npos);
  CHECK(out.find("earliest time of impact: ") != std::string::npos);
  const json r = read_json(dir / "r.json");
  CHECK(r["format"] == "ccdlab-mesh-ccd/1");
  CHECK(r["frames"] == json::array({f0, f1}));
  CHECK(r["options"]["cull"] == "mesh_sweep");
  CHECK(r["options"]["separation"] == 0.001);
  for (const char* k : {"read", "boxes", "broad", "narrow"}) CHECK(r["seconds"][k].get<double>() >= 0);
  CHECK(r["peak_memory_bytes"].get<long long>() > 0);
  CHECK(r["exact"].is_null());

  // The same frames in memory: the same counts and collisions.
  const auto m = ccd::cloth::generate_mesh_frames("crumpled", 400, 3);
  ccd::cloth::MeshCcdOptions o;
  o.separation = 0.001;
  const auto lib = ccd::cloth::mesh_ccd(m.x0, m.x1, m.faces, o);
  CHECK(r["vertices"] == lib.vertices);
  CHECK(r["edges"] == lib.edges);
  CHECK(r["faces"] == lib.faces);
  CHECK(r["candidates"]["vf"] == lib.candidates_vf);
  CHECK(r["candidates"]["ee"] == lib.candidates_ee);
  CHECK(r["collisions"]["vf"] == json(lib.vf));
  CHECK(r["collisions"]["ee"] == json(lib.ee));
  CHECK(!lib.vf.empty());
  REQUIRE(lib.toi);
  CHECK(r["toi"]["time"] == lib.toi->time);

  // --exact: the collisions the exact reference confirms, and the kernel's false positives;
  // together the kernel's hits. brute force finds the same; thread counts change nothing.
  // (at separation 0: the exact reference is slow at a separation that is not a short dyadic)
  REQUIRE(run("ccd " + f0 + " " + f1 + " --quiet -o " + (dir / "k.json"), dir) == 0);
  const json k = read_json(dir / "k.json");
  REQUIRE(run("ccd " + f0 + " " + f1 + " --exact --quiet -o " + (dir / "e.json"), dir) == 0);
  const json e = read_json(dir / "e.json");
  REQUIRE(e["exact"].is_object());
  CHECK(e["collisions"]["vf"].size() + e["exact"]["false_positives"]["vf"].size() == k["collisions"]["vf"].size());
  CHECK(e["collisions"]["ee"].size() + e["exact"]["false_positives"]["ee"].size() == k["collisions"]["ee"].size());
  CHECK(!e["collisions"]["vf"].empty());
  REQUIRE(run("ccd " + f0 + " " + f1 + " --exact --cull brute --threads 1 --quiet -o " +
                  (dir / "b.json"),
              dir) == 0);
  CHECK(read_json(dir / "b.json")["collisions"] == e["collisions"]);
  REQUIRE(run("ccd " + f0 + " " + f1 + " --separation 0.001 --threads 1 --quiet -o " + (dir / "t1.json"), dir) == 0);
  REQUIRE(run("ccd " + f0 + " " + f1 + " --separation 0.001 --threads 7 --quiet -o " + (dir / "t7.json"), dir) == 0);
  CHECK(without_timing(read_json(dir / "t1.json")) == without_timing(read_json(dir / "t7.json")));
  CHECK(without_timing(read_json(dir / "t1.json")) == without_timing(r));
}

TEST_CASE("ccdlab ccd on mesh frames refuses bad input: exit 2, one line, nothing written", "[cloth][cli][mesh_ccd]") {
  Folder dir;
  const std::vector<std::string> v4 = {"0 0 0", "1 0 0", "0 1 0", "0.25 0.25 1"};
  write_ply(dir / "a.ply", v4, {"3 0 1 2", "3 1 2 3"});
  write_ply(dir / "b.ply", {"0 0 0", "1 0 0", "0 1 0", "0.25 0.25 -1"}, {"3 0 1 2", "3 1 2 3"});
  write_ply(dir / "three.ply", {"0 0 0", "1 0 0", "0 1 0"}, {"3 0 1 2", "3 1 2 0"});
  write_ply(dir / "far.ply", v4, {"3 0 1 2", "3 1 2 9001"});
  write_ply(dir / "repeat.ply", v4, {"3 0 1 2", "3 1 3 3"});
  write_ply(dir / "repeat1.ply", {"0 0 0", "1 0 0", "0 1 0", "0.25 0.25 -1"}, {"3 0 1 2", "3 1 3 3"});
  REQUIRE(run("ccd " + (dir / "a.ply") + " " + (dir / "b.ply") + " --quiet -o " + (dir / "ok.json"), dir) == 0);
  CHECK(read_json(dir / "ok.json")["collisions"]["vf"] == json::parse("[[3, 0]]"));
  struct Case {
    std::string args, message;  // message: a part of the error line
  };
  const Case cases[] = {
      {(dir / "a.ply") + " " + (dir / "missing.ply"), "missing.ply"},
      {(dir / "a.ply") + " " + (dir / "three.ply"), "three.ply"},
      {(dir / "a.ply") + " " + (dir / "far.ply"), "far.ply: face 1"},
      {(dir / "repeat.ply") + " " + (dir / "repeat1.ply"), "repeat.ply: face 1: vertex 3 repeated"},
      {(dir / "a.ply") + " " + (dir / "b.ply") + " --cull nope", "unknown culler 'nope'"},
      {(dir / "a.ply") + " " + (dir / "b.ply") + " --separation -1", "--separation"},
      {(dir / "a.ply") + " " + (dir / "b.ply") + " --kind vf", "--kind is for query files"},
      {(dir / "a.ply") + " " + (dir / "b.ply") + " --threads x", "--threads"},
      {(dir / "a.ply"), "two frame files"},
      {(dir / "a.ply") + " " + (dir / "b.ply") + " " + (dir / "b.ply"), "two frame files"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    std::string err;
    CHECK(run("ccd " + c.args + " --quiet -o " + (dir / "r.json"), dir, nullptr, &err) == 2);
    CHECK(err.find(c.message) != std::string::npos);
    CHECK(err.rfind("ccdlab ccd: ", 0) == 0);
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir / "r.json"));
  }
  std::string help;
  REQUIRE(run("ccd --help", dir, &help) == 0);
  CHECK(help.find("ccdlab ccd FRAME0 FRAME1") != std::string::npos);
}

TEST_CASE("ccdlab mesh-frames writes every generator and a cloth run's states", "[cloth][cli][mesh_ccd]") {
  Folder dir;
  for (const std::string name : {"sheet_on_sphere", "tori", "crumpled"}) {
    INFO(name);
    REQUIRE(run("mesh-frames " + name + " --faces 100 --ascii -o " + (dir / name), dir) == 0);
    std::string out;
    REQUIRE(run("ccd " + (dir / name + "/frame0.ply") + " " + (dir / name + "/frame1.ply") + " --quiet", dir, &out) == 0);
    CHECK(out.find("collisions (conservative kernel): 0 vertex-face, 0 edge-edge") == std::string::npos);
  }
  REQUIRE(run("mesh-frames drape --n 6 --step 2 -o " + (dir / "drape"), dir) == 0);
  REQUIRE(run("ccd " + (dir / "drape/frame0.ply") + " " + (dir / "drape/frame1.ply") + " --quiet -o " +
                  (dir / "d.json"),
              dir) == 0);
  CHECK(read_json(dir / "d.json")["faces"] == 50);  // 2 x 5 x 5
  std::string err;
  CHECK(run("mesh-frames nope -o " + (dir / "x"), dir, nullptr, &err) == 2);
  CHECK(err.find("nope") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x"));
  CHECK(run("mesh-frames tori --faces 3 -o " + (dir / "x"), dir) == 2);
  CHECK_FALSE(fs::exists(dir / "x"));
}

}  // namespace cli_mesh_ccd_command_test
