// Recorded frames to a scene (ccd/scene/recorded_frames.hpp, `ccdlab import`): the motion
// between frames, rows in any order, time origin, shapes and orientations, every class of
// bad row named by its line and column, and a recorded motion's truth against the same
// scene written directly.
#include <ccd/motion/rotation.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/recorded_frames.hpp>
#include <ccd/truth/ground_truth.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

namespace ccd_scene_recorded_frames_test {

using ccd::Vec3;

namespace {

ccd::FrameImport import_text(const std::string& text, const ccd::FrameImportOptions& o = {}) {
  std::istringstream in(text);
  return ccd::import_frames(in, "frames.csv", o);
}

std::string error_of(const std::string& text, const ccd::FrameImportOptions& o = {}) {
  try {
    import_text(text, o);
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "";
}

// Every body's centre at the given times, as CSV rows (body,t,x,y,z,radius).
std::string frames_of(const ccd::Scene& s, const std::vector<double>& times) {
  const ccd::Trajectories traj(s);
  std::string text = "body,t,x,y,z,radius\n";
  char line[256];
  for (const double t : times)
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
      const Vec3 p = traj.position(i, t);
      std::snprintf(line, sizeof line, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g\n", i, t, p.x(), p.y(), p.z(),
                    s.bodies[i].radius);
      text += line;
    }
  return text;
}

}  // namespace

TEST_CASE("recorded frames: linear between frames, rows in any order", "[scene][import]") {
  // Body 1's rows come first, times out of order, spaces around cells, a blank line.
  const auto r = import_text(
      "t, body, x, y, z, radius\n"
      "0.5, 1, 4, 1, 0, 0.25\n"
      "1.0, 0, 2, 2, 0, 0.5\n"
      "0.0, 1, 4, 0, 0, 0.25\n"
      "\n"
      "1.0, 1, 4, 1, 0, 0.25\n"
      "0.0, 0, 0, 0, 0, 0.5\n"
      "0.25, 0, 1, 0, 0, 0.5\n");
  const ccd::Scene& s = r.scene;
  CHECK(r.frames == 6);
  CHECK(r.labels == std::vector<std::string>{"0", "1"});
  CHECK(s.horizon == 1.0);
  CHECK(s.gravity == Vec3::Zero());
  CHECK_FALSE(s.box);
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[0].radius == 0.5);
  CHECK(s.bodies[0].velocity == Vec3(4, 0, 0));
  REQUIRE(s.bodies[0].velocity_changes.size() == 1);
  CHECK(s.bodies[0].velocity_changes[0].t == 0.25);
  CHECK(s.bodies[0].velocity_changes[0].velocity == Vec3(4.0 / 3.0, 8.0 / 3.0, 0));
  CHECK(s.bodies[1].velocity == Vec3(0, 2, 0));
  REQUIRE(s.bodies[1].velocity_changes.size() == 1);  // to rest at 0.5
  CHECK(s.bodies[1].velocity_changes[0].velocity == Vec3::Zero());
  const ccd::Trajectories traj(s);
  CHECK(traj.position(1, 0.5) == Vec3(4, 1, 0));
  CHECK(traj.position(0, 1.0).isApprox(Vec3(2, 2, 0), 1e-15));
}

TEST_CASE("recorded frames: scene time 0 is the file's first time, unchanged velocities are left out",
          "[scene][import]") {
  const auto r = import_text("body,t,x,y,z,radius\nball,10,0,0,0,1\nball,10.5,1,0,0,1\nball,11,2,0,0,1\n"
                             "ball,12,2,0,0,1\n");
  CHECK(r.time_origin == 10.0);
  CHECK(r.scene.horizon == 2.0);
  CHECK(r.labels == std::vector<std::string>{"ball"});
  REQUIRE(r.scene.bodies[0].velocity_changes.size() == 1);  // 2 m/s until t = 1 (file 11), then rest
  CHECK(r.scene.bodies[0].velocity_changes[0].t == 1.0);
  CHECK(r.scene.bodies[0].velocity_changes[0].velocity == Vec3::Zero());
}

TEST_CASE("recorded frames: labels order numerically when all are integers, else as strings", "[scene][import]") {
  const std::string rows = "body,t,x,y,z,radius\n10,0,0,0,0,1\n9,0,5,0,0,1\n10,1,0,0,0,1\n9,1,5,0,0,1\n";
  CHECK(import_text(rows).labels == std::vector<std::string>{"9", "10"});
  const std::string named = "body,t,x,y,z,radius\nb,0,0,0,0,1\na,0,5,0,0,1\nb,1,0,0,0,1\na,1,5,0,0,1\n";
  CHECK(import_text(named).labels == std::vector<std::string>{"a", "b"});
  CHECK(import_text(named).scene.bodies[0].position == Vec3(5, 0, 0));
}

TEST_CASE("recorded frames: positions at the frames do not drift over many frames", "[scene][import]") {
  // 2000 frames of decimal data (not dyadic): each interval's velocity is taken from the
  // model's own position, so the error at every frame stays at one rounding.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::string text = "body,t,x,y,z,radius\n";
  std::vector<Vec3> p;
  char line[256];
  Vec3 x(1000.1, -3.3, 0.7);
  for (int k = 0; k <= 2000; ++k) {
    p.push_back(x);
    std::snprintf(line, sizeof line, "0,%.17g,%.17g,%.17g,%.17g,0.1\n", k * 0.01, x.x(), x.y(), x.z());
    text += line;
    x += 0.01 * Vec3(3 * u(rng), 3 * u(rng), 3 * u(rng));
  }
  const auto r = import_text(text);
  const ccd::Trajectories traj(r.scene);
  double worst = 0.0;
  for (int k = 0; k <= 2000; ++k) worst = std::max(worst, (traj.position(0, k * 0.01) - p[static_cast<std::size_t>(k)]).norm());
  CHECK(worst <= 1e-11);  // |x| ~ 1e3: a few ulps, not 2000 of them
}

TEST_CASE("recorded frames: shapes and orientations, constant angular velocity along the shortest arc",
          "[scene][import]") {
  // A box turning about z by a quarter turn per half second, then resting; a capsule from
  // --shapes; a sphere whose orientation columns are ignored.
  const double c = std::sqrt(0.5);
  const std::string text =
      "body,t,x,y,z,shape,radius,qw,qx,qy,qz\n"
      "0,0,0,0,0,\"box:1,0.5,0.25\",,1,0,0,0\n"
      "0,0.5,0,0,0,\"box:1,0.5,0.25\",,0.70710678118654757,0,0,0.70710678118654757\n"
      "0,1,0,0,0,\"box:1,0.5,0.25\",,-0.70710678118654757,0,0,-0.70710678118654757\n"  // the same pose, sign flipped
      "1,0,8,0,0,stick,,1,0,0,0\n"
      "1,1,8,0,0,stick,,1,0,0,0\n"
      "2,0,16,0,0,,0.5,0.5,0.5,0.5,0.5\n"
      "2,1,16,1,0,,0.5,1,0,0,0\n";
  ccd::FrameImportOptions o;
  o.shapes = nlohmann::json::parse(R"([{"name": "stick", "kind": "capsule", "half_length": 1, "radius": 0.125}])");
  const auto r = import_text(text, o);
  const ccd::Scene& s = r.scene;
  REQUIRE(s.rigid.size() == 3);
  CHECK(s.shapes.size() == 2);
  CHECK(s.kind(0) == ccd::ShapeKind::Box);
  CHECK(s.kind(1) == ccd::ShapeKind::Capsule);
  CHECK(s.kind(2) == ccd::ShapeKind::Sphere);
  CHECK(s.rigid[0].angular_velocity.isApprox(Vec3(0, 0, M_PI), 1e-14));
  CHECK(s.rigid[0].angular_velocity_changes.size() == 1);
  CHECK(s.rigid[0].angular_velocity_changes[0].angular_velocity.norm() <= 1e-14);
  CHECK(s.rigid[2].orientation.coeffs() == Eigen::Quaterniond::Identity().coeffs());  // a sphere: not used
  const ccd::Rotations rot(s);
  const Eigen::Quaterniond q = rot.orientation(0, 0.5);
  CHECK(std::fabs(q.w() - c) <= 1e-15);
  CHECK(std::fabs(q.z() - c) <= 1e-15);
  CHECK(rot.orientation(0, 1.0).angularDistance(q) <= 1e-14);
}

TEST_CASE("recorded frames: inline shapes", "[scene][import]") {
  const auto r = import_text("body,t,x,y,z,shape\n0,0,0,0,0,sphere:0.5\n0,1,1,0,0,sphere:0.5\n"
                             "1,0,4,0,0,\"capsule:1,0.125\"\n1,1,4,0,0,\"capsule:1,0.125\"\n");
  REQUIRE(r.scene.shapes.size() == 2);
  CHECK(r.scene.shapes[0].kind == ccd::ShapeKind::Sphere);
  CHECK(r.scene.shapes[1].kind == ccd::ShapeKind::Capsule);
  CHECK(r.scene.shapes[1].half_length == 1.0);
  CHECK(r.scene.bodies[0].radius == r.scene.shapes[0].enclosing_radius());
  CHECK(error_of("body,t,x,y,z,shape\n0,0,0,0,0,capsule:1\n0,1,1,0,0,capsule:1\n") ==
        "frames.csv: line 2: shape: shape \"capsule:1\" needs 2 size(s), got 1");
  CHECK(error_of("body,t,x,y,z,shape\n0,0,0,0,0,sphere:-1\n0,1,1,0,0,sphere:-1\n") ==
        "frames.csv: line 2: shape: shape \"sphere:-1\": sizes must be numbers > 0 (sphere:R)");
  CHECK(error_of("body,t,x,y,z,shape\n0,0,0,0,0,\"box:1,1\n") == "frames.csv: line 2: unclosed quote");
  // A bad named shape is reported against the shapes' own file.
  ccd::FrameImportOptions o;
  o.shapes = nlohmann::json::parse(R"([{"name": "crate", "kind": "box", "half_extents": [1, 0, 1]}])");
  o.shapes_file = "shapes.json";
  CHECK(error_of("body,t,x,y,z,shape\n0,0,0,0,0,crate\n0,1,1,0,0,crate\n", o) ==
        "shapes.json: shapes[0].half_extents[1]: must be > 0");
}

TEST_CASE("recorded frames: every bad row is named by line and column", "[scene][import]") {
  const std::string head = "body,t,x,y,z,radius\n";
  CHECK(error_of("") == "frames.csv: empty: needs a header row (body,t,x,y,z,radius)");
  CHECK(error_of("body,t,x,y,radius\n0,0,0,0,1\n") == "frames.csv: line 1: header: missing column \"z\"");
  CHECK(error_of("body,t,x,y,z,radius,mass\n") ==
        "frames.csv: line 1: header: unknown column \"mass\" (known: body, t, x, y, z, radius, shape, qw, qx, qy, qz)");
  CHECK(error_of("body,t,x,y,z,radius,qw\n") == "frames.csv: line 1: header: give all four of qw, qx, qy, qz or none");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,1,0,0\n") == "frames.csv: line 3: has 4 cells, the header 6");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,1,0,abc,0,1\n") == "frames.csv: line 3: y: must be a finite number, got \"abc\"");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,nan,0,0,0,1\n") == "frames.csv: line 3: t: must be a finite number, got \"nan\"");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,1,0,,0,1\n") == "frames.csv: line 3: y: missing number");
  CHECK(error_of(head + "0,0,0,0,0,0\n0,1,0,0,0,0\n") == "frames.csv: line 2: radius: must be > 0");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,1,0,0,0,-2\n") == "frames.csv: line 3: radius: must be > 0");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,1,0,0,0,2\n") ==
        "frames.csv: line 3: radius: body \"0\" has radius 1.000000 on line 2; a body's radius cannot change");
  CHECK(error_of(head + "0,1,0,0,0,1\n0,0,0,0,0,1\n0,1,5,0,0,1\n") ==
        "frames.csv: line 4: t: body \"0\" has two frames at t = 1.000000 (lines 2 and 4)");
  CHECK(error_of(head + "0,0,0,0,0,1\n1,0.5,5,0,0,1\n0,1,0,0,0,1\n1,1,5,0,0,1\n") ==
        "frames.csv: line 3: t: body \"1\" starts at t = 0.500000, after the file's first time 0.000000 (every body "
        "needs a frame at the first and the last time)");
  CHECK(error_of(head + "0,0,0,0,0,1\n1,0,5,0,0,1\n0,1,0,0,0,1\n1,0.5,5,0,0,1\n") ==
        "frames.csv: line 5: t: body \"1\" ends at t = 0.500000, before the file's last time 1.000000 (every body "
        "needs a frame at the first and the last time)");
  CHECK(error_of(head + "0,0,0,0,0,1\n0,0,0,0,0,1\n0,1,0,0,0,1\n") ==
        "frames.csv: line 3: t: body \"0\" has two frames at t = 0.000000 (lines 2 and 3)");
  CHECK(error_of(head + "0,0,0,0,0,1\n") == "frames.csv: t: needs at least two distinct times (the horizon would be 0)");
  CHECK(error_of(head) == "frames.csv: line 1: no frames after the header");
  CHECK(error_of("body,t,x,y,z\n0,0,0,0,0\n0,1,0,0,0\n") ==
        "frames.csv: line 2: header: no radius or shape column: give --radius R for every body");
  CHECK(error_of(head + ",0,0,0,0,1\n") == "frames.csv: line 2: body: missing body label");
  CHECK(error_of(head + "07,0,0,0,0,1\n07,1,0,0,0,1\n") == "frames.csv: line 2: body: label \"07\" has a leading zero");
  const std::string quat = "body,t,x,y,z,shape,qw,qx,qy,qz\n";
  CHECK(error_of(quat + "0,0,0,0,0,sphere:1,1,0,0,0\n0,1,0,0,0,sphere:1,1.001,0,0,0\n") ==
        "frames.csv: line 3: qw,qx,qy,qz: must be a unit quaternion within 1e-6 (|q| = 1.001000)");
  CHECK(error_of(quat + "0,0,0,0,0,sphere:1,1,0,0,0\n0,1,0,0,0,sphere:2,1,0,0,0\n") ==
        "frames.csv: line 3: shape: body \"0\" has shape \"sphere:1\" on line 2; a body's shape cannot change");
  CHECK(error_of(quat + "0,0,0,0,0,rock,1,0,0,0\n0,1,0,0,0,rock,1,0,0,0\n") ==
        "frames.csv: line 2: shape: unknown shape \"rock\" (not in --shapes; inline shapes are sphere:R, "
        "capsule:HALF_LENGTH,R, box:HX,HY,HZ)");
  CHECK(error_of("body,t,x,y,z,radius,shape\n0,0,0,0,0,1,sphere:1\n") ==
        "frames.csv: line 2: radius: not allowed with a shape (the shape gives the size)");
  CHECK(error_of("body,t,x,y,z,radius,shape\n0,0,0,0,0,,\n") == "frames.csv: line 2: radius: missing number (or give a shape)");
  // Whatever the magnitude limits of a scene refuse is refused here too (named in the scene).
  CHECK(error_of(head + "0,0,0,0,0,1\n0,1e-300,1e300,0,0,1\n").find("frames.csv: bodies[0].velocity") == 0);
}

TEST_CASE("recorded frames: a body whose time goes backwards is named at that line", "[scene][import]") {
  // Four bodies, one row each per frame time k / 120 s (lines 4k + 2 to 4k + 5). Body 3's
  // row of frame 10 (line 45) says t = 0.001 instead of 0.083333: from there on its rows
  // are copied with the time that went wrong, so its last time is frame 5's (line 25),
  // before the file's last time. The error names line 45 and says t goes backwards there,
  // not line 25, where nothing is wrong.
  std::string text = "body,t,x,y,z,radius\n";
  char row[128];
  for (int k = 0; k <= 20; ++k)
    for (int b = 0; b < 4; ++b) {
      const double t = b == 3 && k >= 10 ? 0.001 * (k - 9) : k / 120.0;
      std::snprintf(row, sizeof row, "%d,%.17g,%d,0,0,0.25\n", b, t, 2 * b);
      text += row;
    }
  CHECK(error_of(text) ==
        "frames.csv: line 45: t: body \"3\" goes backwards here (t = 0.001000 after t = 0.075000 on line 41), so it "
        "ends at t = 0.075000, before the file's last time 0.166667 (every body needs a frame at the first and the last "
        "time)");
  // A body that starts late because its first row went back in time: the same line.
  CHECK(error_of("body,t,x,y,z,radius\n0,0,0,0,0,1\n1,0.5,5,0,0,1\n0,1,0,0,0,1\n1,0.2,5,0,0,1\n1,1,5,0,0,1\n") ==
        "frames.csv: line 5: t: body \"1\" goes backwards here (t = 0.200000 after t = 0.500000 on line 3), so it "
        "starts at t = 0.200000, after the file's first time 0.000000 (every body needs a frame at the first and the "
        "last time)");
  // Rows in any order stay allowed: backwards steps are only named when a body misses the
  // file's first or last time.
  CHECK(import_text("body,t,x,y,z,radius\n0,1,0,0,0,1\n1,1,5,0,0,1\n0,0,0,0,0,1\n1,0,5,0,0,1\n").scene.bodies.size() ==
        2);
}

TEST_CASE("recorded frames: a recorded motion's truth equals the truth of the scene it records", "[scene][import]") {
  // A scene written directly: bodies with velocity changes at dyadic frame times (every
  // 1/8 s), no walls, no gravity. Its centres at the frames, imported, give a scene with
  // the same motion, and so the same truth, event for event and bit for bit.
  std::mt19937_64 rng(21);
  std::uniform_int_distribution<int> step(-16, 16);
  ccd::Scene direct;
  direct.horizon = 2.0;
  for (int i = 0; i < 40; ++i) {
    ccd::Body b;
    b.radius = 0.5;
    b.position = Vec3(step(rng) / 4.0, step(rng) / 4.0, step(rng) / 4.0);
    b.velocity = Vec3(step(rng) / 2.0, step(rng) / 2.0, step(rng) / 2.0);
    Vec3 v = b.velocity;
    for (int k = 1; k < 16; ++k) {
      const Vec3 w(step(rng) / 2.0, step(rng) / 2.0, step(rng) / 2.0);
      if (step(rng) > 0 && w != v) b.velocity_changes.push_back({k / 8.0, v = w});
    }
    direct.bodies.push_back(b);
  }
  std::vector<double> times;
  for (int k = 0; k <= 16; ++k) times.push_back(k / 8.0);
  const auto imported = import_text(frames_of(direct, times));
  const auto truth_direct = ccd::compute_truth(ccd::Trajectories(direct));
  const auto truth_imported = ccd::compute_truth(ccd::Trajectories(imported.scene));
  CHECK(truth_direct.size() >= 20);
  CHECK(truth_imported == truth_direct);
  for (std::size_t i = 0; i < direct.bodies.size(); ++i) {
    CHECK(imported.scene.bodies[i].velocity == direct.bodies[i].velocity);
    REQUIRE(imported.scene.bodies[i].velocity_changes.size() == direct.bodies[i].velocity_changes.size());
    for (std::size_t k = 0; k < direct.bodies[i].velocity_changes.size(); ++k) {
      CHECK(imported.scene.bodies[i].velocity_changes[k].t == direct.bodies[i].velocity_changes[k].t);
      CHECK(imported.scene.bodies[i].velocity_changes[k].velocity == direct.bodies[i].velocity_changes[k].velocity);
    }
  }
}

}  // namespace ccd_scene_recorded_frames_test
