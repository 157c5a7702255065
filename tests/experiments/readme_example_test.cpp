// The library example of README.md, compiled and run, so the README stays true.
#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <string>

#define main readme_example_main
// ---- README example begins (keep in sync with README.md, "Library") ----
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/truth.hpp>
#include <iostream>

int main() {
  const ccd::Scene scene = ccd::load_scene(CCDLAB_SOURCE_DIR "/data/scenes/default.json");
  const ccd::Trajectories centres(scene);                 // exact: wall reflections solved
  const ccd::RigidMotion motion(scene, centres);          // the scene's motion: centres, shapes, spin
  const ccd::Truth truth = ccd::compute_truth(motion, scene.scenery);  // every contact
  const ccd::BoundSpec capsule = ccd::parse_bound("capsule");  // a conservative space-time bound
  ccd::StepPipeline pipeline(capsule.make(), capsule.info->knowledge,
                             ccd::find_broad_phase("grid").make());  // culls with the bound's boxes
  const double t0 = 0.0, t1 = 1.0 / 60.0;                 // one step
  std::vector<ccd::BodyState> start;
  ccd::StateCursor(centres).evaluate(t0, start);          // every body's state at t0
  ccd::StepResult step;                                   // bound -> broad phase -> test -> narrow
  pipeline.run({.t0 = t0, .t1 = t1, .start = start, .exact = &centres, .walls = scene.box, .motion = &motion}, step);
  for (const ccd::PairContact& c : step.bodies.contacts)
    std::cout << c.pair.a << " and " << c.pair.b << " touch at t = " << c.contact.toi << "\n";
  std::cout << truth.events.size() << " contact events in " << scene.horizon << " s\n";
  return 0;
}
// ---- README example ends ----
#undef main

namespace experiments_readme_example_test {

TEST_CASE("the README's library example runs and agrees with the ground truth", "[readme]") {
  std::ostringstream example_out;
  std::streambuf* saved = std::cout.rdbuf(example_out.rdbuf());
  const int rc = readme_example_main();
  std::cout.rdbuf(saved);
  REQUIRE(rc == 0);
  const ccd::Scene scene = ccd::load_scene(CCDLAB_SOURCE_DIR "/data/scenes/default.json");
  const ccd::Trajectories motion(scene);
  const auto events = ccd::compute_truth(motion);
  // Every event that starts in the first step must have been printed.
  std::size_t first_step = 0;
  for (const auto& e : events) first_step += e.enter <= 1.0 / 60.0;
  const std::string out = example_out.str();
  CHECK(std::count(out.begin(), out.end(), '\n') >= static_cast<long>(first_step) + 1);
  CHECK(out.find(std::to_string(events.size()) + " contact events") != std::string::npos);
}

TEST_CASE("the README shows the example this file compiles", "[readme]") {
  // The example between the markers above, as README.md must show it: the scene path
  // relative to the repository and no explicit return.
  auto slurp = [](const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  };
  const std::string self = slurp(CCDLAB_SOURCE_DIR "/tests/experiments/readme_example_test.cpp");
  const std::string begin = "(keep in sync with README.md, \"Library\") ----\n";
  const std::size_t a = self.find(begin);
  const std::size_t b = self.find("// ---- README example ends ----");
  REQUIRE(a != std::string::npos);
  REQUIRE(b != std::string::npos);
  std::string expected = self.substr(a + begin.size(), b - a - begin.size());
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = expected.find(from);
    REQUIRE(at != std::string::npos);
    expected.replace(at, from.size(), to);
  };
  replace("CCDLAB_SOURCE_DIR \"/data/scenes/default.json\"", "\"data/scenes/default.json\"");
  replace("  return 0;\n", "");
  const std::string readme = slurp(CCDLAB_SOURCE_DIR "/README.md");
  CHECK(readme.find("```cpp\n" + expected + "```\n") != std::string::npos);
}

}  // namespace experiments_readme_example_test
