// The volumes `ccdlab view` puts in the page (experiments/view_volumes.hpp): for every bound
// of the registry, fixed steps and `@earliest` windows, they are the bound's own volumes
// (rebuilt here with Bound::prepare over the same window) and their hull is the box the
// bound wrote; a page over the size limit keeps the windows of the missed contacts.
#include "../../experiments/view_volumes.hpp"

#include <bounds/registry.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scene_io.hpp>
#include <pipeline/window_policy.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace experiments_view_volumes_test {

using nlohmann::json;

namespace {

ccd::Scene tunnel() {
  return ccd::scene_from_json(json::parse(R"({"format": "ccdlab-scene/1", "horizon": 1.0, "gravity": [0, -2, 0],
    "box": {"min": [-10, -10, -10], "max": [10, 10, 10]},
    "bodies": [{"radius": 0.5, "position": [0, 0, 0], "velocity": [10, 1, 0]},
               {"radius": 0.5, "position": [5, 0, 0], "velocity": [-10, 1, 0]},
               {"radius": 0.25, "position": [8, 5, 0], "velocity": [40, 0, 3]}]})"),
                              "scene.json");
}

// 9 significant digits (the page's numbers) against the value.
bool near(double page, double value) { return std::abs(page - value) <= 1e-8 * (1.0 + std::abs(value)); }
bool near3(const json& page, const ccd::Vec3& v) {
  return near(page[0].get<double>(), v[0]) && near(page[1].get<double>(), v[1]) && near(page[2].get<double>(), v[2]);
}

bool same_volume(const json& p, const ccd::Volume& v) {
  if (p["kind"] != std::string(ccd::to_string(v.kind)) || !near(p["t"][0].get<double>(), v.t0) || !near(p["t"][1].get<double>(), v.t1)) return false;
  switch (v.kind) {
    case ccd::Volume::Kind::Box: return near3(p["lo"], v.a) && near3(p["hi"], v.b);
    case ccd::Volume::Kind::Sphere: return near3(p["c"], v.a) && near(p["r"].get<double>(), v.radius);
    case ccd::Volume::Kind::Capsule: return near3(p["a"], v.a) && near3(p["b"], v.b) && near(p["r"].get<double>(), v.radius);
    case ccd::Volume::Kind::OrientedBox:
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
          if (!near(p["axes"][3 * c + k].get<double>(), v.axes(k, c))) return false;
      return near3(p["c"], v.a) && near3(p["half"], v.b);
  }
  return false;
}

ccd::Aabb page_hull(const json& p) {
  ccd::Volume v;
  const auto vec = [](const json& a) { return ccd::Vec3(a[0].get<double>(), a[1].get<double>(), a[2].get<double>()); };
  if (p["kind"] == "box") v = ccd::Volume::box({vec(p["lo"]), vec(p["hi"])}, 0, 0);
  if (p["kind"] == "sphere") v = ccd::Volume::sphere(vec(p["c"]), p["r"].get<double>(), 0, 0);
  if (p["kind"] == "capsule") v = ccd::Volume::capsule(vec(p["a"]), vec(p["b"]), p["r"].get<double>(), 0, 0);
  if (p["kind"] == "oriented_box") {
    Eigen::Matrix3d axes;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) axes(k, c) = p["axes"][3 * c + k].get<double>();
    v = ccd::Volume::oriented_box(vec(p["c"]), axes, vec(p["half"]), 0, 0);
  }
  return v.hull();
}

// Checks run `r` of the page against `bound` rebuilt over each exported window.
void check_run(const ccd::Scene& scene, const ccd::Trajectories& traj, const json& run, const std::string& bound_spec) {
  const ccd::BoundSpec bs = ccd::parse_bound(bound_spec);
  const auto bound = bs.make();
  const ccd::RigidMotion motion(scene, traj);
  const bool instant = bs.info->knowledge == ccd::Knowledge::Instant;
  const bool all = run["volumes"]["coverage"] == "all";
  const bool hull_is_box = bs.info->name != "capsule" && bs.info->name != "horn_sat";
  std::vector<ccd::BodyState> start(traj.size());
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::Volume> own;
  long windows = 0, failed = 0;
  for (std::size_t i = 0; i < traj.size(); ++i) {
    const json& list = run["volumes"]["bodies"][i];
    double last_end = 0.0;
    for (const json& entry : list) {
      ++windows;
      const double w0 = entry[0].get<double>(), w1 = entry[1].get<double>();
      if (all) CHECK(near(w0, last_end));  // the windows tile the horizon
      last_end = w1;
      ccd::StepContext ctx;
      ctx.t0 = w0;
      ctx.t1 = instant ? w0 : w1;
      for (std::size_t j = 0; j < traj.size(); ++j) start[j] = {traj.position(j, w0), traj.velocity(j, w0), traj.radius(j)};
      ctx.start = start;
      ctx.exact = bs.info->knowledge == ccd::Knowledge::Exact ? &traj : nullptr;
      ctx.acceleration_bound = run["acceleration_bound"].get<double>();
      ctx.walls = scene.box;
      ctx.motion = &motion;
      bound->prepare(ctx, boxes);
      own.clear();
      bound->volumes(static_cast<std::uint32_t>(i), own);
      const json& page = entry[2];
      bool same = page.size() == own.size();
      for (std::size_t k = 0; same && k < own.size(); ++k) same = same_volume(page[k], own[k]);
      ccd::Aabb hull = page_hull(page[0]);
      for (const json& v : page) hull.merge(page_hull(v));
      const ccd::Aabb& box = boxes[i];
      const double tol = 1e-7 * (1.0 + box.lo.cwiseAbs().cwiseMax(box.hi.cwiseAbs()).maxCoeff());
      const bool inside = (hull.lo.array() <= box.lo.array() + tol).all() && (box.hi.array() <= hull.hi.array() + tol).all();
      const bool equal = inside && (box.lo.array() <= hull.lo.array() + tol).all() && (hull.hi.array() <= box.hi.array() + tol).all();
      if ((!same || !(hull_is_box ? equal : inside)) && ++failed <= 3)
        FAIL_CHECK(run["method"].get<std::string>() << ": body " << i << " over [" << w0 << ", " << w1 << "]: "
                                                    << (same ? "hull against the box" : "volumes differ") << ": "
                                                    << page.dump());
    }
    if (all) CHECK(near(last_end, scene.horizon));
  }
  CHECK(failed == 0);
  CHECK(windows >= (all ? static_cast<long>(traj.size()) : 1));
}

json one_run(const std::string& method, double dt, double acceleration_bound) {
  return json::array({json{{"method", method}, {"dt", dt}, {"acceleration_bound", acceleration_bound}}});
}

}  // namespace

TEST_CASE("view volumes: every bound's own volumes over its fixed steps and its earliest windows", "[view][volumes]") {
  const std::string scene_name = GENERATE(as<std::string>{}, "tunnel", "rigid-example");
  const ccd::Scene scene = scene_name == "tunnel"
                               ? tunnel()
                               : ccd::load_scene(std::string(CCDLAB_SOURCE_DIR) + "/data/scenes/rigid-example.json");
  const ccd::Trajectories traj(scene);
  const double A = scene.max_acceleration();
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    std::vector<std::string> methods{std::string(b.name) + "/brute"};
    if (b.knowledge != ccd::Knowledge::Instant) {
      methods.push_back(std::string(b.name) + "/brute@earliest");
      methods.push_back(std::string(b.name) + "/brute@earliest:reach=0.5,align=0");
    }
    for (const std::string& m : methods) {
      INFO(scene_name << ": " << m);
      json runs = one_run(m, 0.25, A);
      ccdlab::add_run_volumes(scene, traj, runs);
      REQUIRE(runs[0]["volumes"]["coverage"] == "all");
      REQUIRE(runs[0]["volumes"]["bodies"].size() == traj.size());
      check_run(scene, traj, runs[0], std::string(b.name));
    }
  }
}

TEST_CASE("view volumes: earliest windows are each body's own", "[view][volumes]") {
  // reach = 2: each body moves at most 2 x the mean radius (5/6 m) per window, |v| w +
  // A w^2 / 2 <= 5/6 with A = 2: bodies 0 and 1 (about 10 m/s) get dt / 4 = 1/16 s, body 2
  // (about 40 m/s) dt / 16 = 1/64 s, aligned on multiples of their lengths.
  const ccd::Scene scene = tunnel();
  const ccd::Trajectories traj(scene);
  json runs = one_run("capsule/sap@earliest:reach=2", 0.25, scene.max_acceleration());
  ccdlab::add_run_volumes(scene, traj, runs);
  const json& bodies = runs[0]["volumes"]["bodies"];
  CHECK(bodies[0].size() == 16);
  CHECK(bodies[1].size() == 16);
  CHECK(bodies[2].size() == 64);
  CHECK(bodies[2][1][0].get<double>() == 1.0 / 64);
  check_run(scene, traj, runs[0], "capsule");
}

TEST_CASE("view volumes: a page over the limit keeps the windows of the missed contacts", "[view][volumes]") {
  const ccd::Scene scene = tunnel();
  const ccd::Trajectories traj(scene);
  // dt = 1e-5: 1e5 steps x 3 bodies, over kMaxViewVolumes.
  json runs = one_run("aabb/sap", 1e-5, 0.0);
  runs[0]["missed_events"] = json::array({json{{"a", 0}, {"b", 1}, {"enter", 0.2}, {"exit", 0.3}}});
  ccdlab::add_run_volumes(scene, traj, runs);
  const json& v = runs[0]["volumes"];
  CHECK(v["coverage"] == "missed");
  CHECK(v["reason"].get<std::string>().find("200000 volumes") != std::string::npos);
  REQUIRE(v["bodies"].size() == 3);
  for (int i : {0, 1}) {
    REQUIRE(v["bodies"][i].size() == 1);
    const double w0 = v["bodies"][i][0][0], w1 = v["bodies"][i][0][1];
    CHECK(w0 <= 0.25);
    CHECK(0.25 <= w1);
    CHECK(w1 - w0 < 2e-5);
  }
  CHECK(v["bodies"][2].empty());
  check_run(scene, traj, runs[0], "aabb");
}

TEST_CASE("view volumes: a method this build does not know gets none, with the reason", "[view][volumes]") {
  const ccd::Scene scene = tunnel();
  const ccd::Trajectories traj(scene);
  json runs = one_run("warp_drive/sap", 0.25, 0.0);
  ccdlab::add_run_volumes(scene, traj, runs);
  CHECK(runs[0]["volumes"]["coverage"] == "none");
  CHECK(runs[0]["volumes"]["reason"].get<std::string>().find("warp_drive") != std::string::npos);
}

}  // namespace experiments_view_volumes_test
