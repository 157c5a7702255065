// `ccdlab poses`: the CSV's columns and values against the motion model, and every bad
// --times refused with exit 2 and no file written.
#include "cli_support.hpp"

#include <ccd/motion/rotation.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

namespace cli_poses_command_test {

using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;
using ccd::Vec3;

namespace {

const char* kScene = R"({"format": "ccdlab-scene/2", "horizon": 2.0, "gravity": [0, -8, 0],
  "box": {"min": [0, 0, 0], "max": [16, 16, 16]},
  "shapes": [{"name": "plate", "kind": "box", "half_extents": [1, 0.5, 0.0625]}],
  "bodies": [{"shape": "plate", "position": [8, 8, 8], "velocity": [4, 0, 0], "spin": "free",
              "angular_velocity": [1, 2, 6], "orientation": [0.5, 0.5, 0.5, 0.5],
              "angular_velocity_changes": [{"t": 1.25, "angular_velocity": [0, 3, 0]}]},
             {"radius": 0.5, "position": [2, 2, 2], "velocity": [-8, 0, 0]},
             {"shape": "plate", "position": [12, 12, 12], "angular_velocity": [0, 0, 3]}]})";

std::vector<std::vector<double>> read_rows(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("ccdlab poses writes body,t,x,y,z,qw,qx,qy,qz from the motion model", "[cli][poses]") {
  Folder dir;
  std::ofstream(dir / "scene.json") << kScene;
  REQUIRE(run_ccdlab("poses " + dir / "scene.json" + " --times 0:2:0.25 -o " + dir / "poses.csv", dir) == 0);
  std::string header;
  const auto rows = read_rows(ccdlab::test::slurp(dir / "poses.csv"), header);
  CHECK(header == "body,t,x,y,z,qw,qx,qy,qz");
  REQUIRE(rows.size() == 9 * 3);  // 0, 0.25, ..., 2 for three bodies
  const ccd::Scene scene = ccd::load_scene(dir / "scene.json");
  const ccd::Trajectories traj(scene);
  const ccd::Rotations rot(scene);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto& row = rows[r];
    REQUIRE(row.size() == 9);
    const auto body = static_cast<std::size_t>(row[0]);
    const double t = row[1];
    CHECK(body == r % 3);
    CHECK(t == 0.25 * static_cast<double>(r / 3));  // A + k STEP, exactly
    const Vec3 p = traj.position(body, t);
    CHECK(Vec3(row[2], row[3], row[4]) == p);  // 17 digits read back exactly
    ccd::Quat q = rot.orientation(body, t);
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    CHECK(ccd::Quat(row[5], row[6], row[7], row[8]).coeffs() == q.coeffs());
    CHECK(row[5] >= 0.0);
  }
  // The ball bounced off the wall x = 0.5 (it started moving towards it at 8 m/s).
  CHECK(rows[3 * 4 + 1][2] > 2.0);
}

TEST_CASE("ccdlab poses refuses bad --times with exit 2 and writes nothing", "[cli][poses]") {
  Folder dir;
  std::ofstream(dir / "scene.json") << kScene;
  struct Case {
    const char* times;
    const char* message;
  };
  const Case c = GENERATE(Case{"0:1", "--times must be A:B:STEP, got '0:1'"},
                          Case{"0:1:0.1:2", "--times must be A:B:STEP, got '0:1:0.1:2'"},
                          Case{"0:x:0.1", "--times A:B:STEP needs three finite numbers, got '0:x:0.1'"},
                          Case{"0:1:nan", "--times A:B:STEP needs three finite numbers, got '0:1:nan'"},
                          Case{"0:1:0", "--times: STEP must be > 0, got '0:1:0'"},
                          Case{"0:1:-0.5", "--times: STEP must be > 0, got '0:1:-0.5'"},
                          Case{"1:0.5:0.1", "--times: need 0 <= A <= B, got '1:0.5:0.1'"},
                          Case{"-1:1:0.1", "--times: need 0 <= A <= B, got '-1:1:0.1'"},
                          Case{"0:3:0.5", "--times: B must be at most the scene's horizon 2.000000, got '0:3:0.5'"},
                          Case{"0:2:1e-9", "needs 6e+09 rows (2e+09 times x 3 bodies), above the limit 1e+07 without --force"});
  std::string err;
  INFO(c.times);
  CHECK(run_ccdlab("poses " + dir / "scene.json" + " --times " + c.times + " -o " + dir / "poses.csv", dir, nullptr,
                   &err) == 2);
  CHECK(err.find(c.message) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "poses.csv"));
}

TEST_CASE("ccdlab poses: a bad scene names its field, usage errors", "[cli][poses]") {
  Folder dir;
  std::string scene = kScene;
  scene.replace(scene.find("\"spin\": \"free\""), 14, "\"spin\": \"fre\"");
  std::ofstream(dir / "bad.json") << scene;
  std::string err;
  CHECK(run_ccdlab("poses " + dir / "bad.json" + " --times 0:1:0.5 -o " + dir / "p.csv", dir, nullptr, &err) == 2);
  CHECK(err.find("bad.json: bodies[0].spin: unknown spin \"fre\" (prescribed, free)") != std::string::npos);
  CHECK(run_ccdlab("poses " + dir / "bad.json" + " -o " + dir / "p.csv", dir, nullptr, &err) == 2);
  CHECK(err.find("missing --times") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "p.csv"));
}

}  // namespace cli_poses_command_test
