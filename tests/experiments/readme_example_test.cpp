// The library example of README.md, compiled and run, so the README stays true.
#include <algorithm>
#include <catch2/catch.hpp>
#include <sstream>

#define main readme_example_main
// ---- README example begins (keep in sync with README.md, "Library") ----
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <iostream>

int main() {
  const ccd::Scene scene = ccd::load_scene(CCDLAB_SOURCE_DIR "/data/scenes/default.json");
  const ccd::Trajectories motion(scene);                 // exact: wall reflections solved
  const auto events = ccd::compute_truth(motion);        // every contact interval
  auto bound = ccd::parse_bound("capsule").make();       // a conservative space-time bound
  auto broad = ccd::find_broad_phase("grid").make();     // culls with the bound's boxes
  const double t0 = 0.0, t1 = 1.0 / 60.0;                // one step
  std::vector<ccd::BodyState> start;
  for (std::size_t i = 0; i < motion.size(); ++i)
    start.push_back({motion.position(i, t0), motion.velocity(i, t0), motion.radius(i)});
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs;
  bound->prepare({t0, t1, start, &motion, 0.0, scene.box}, boxes);  // one box per body
  broad->find_pairs(boxes, pairs);
  for (auto [a, b] : pairs)
    if (bound->test(a, b, nullptr))
      if (auto toi = ccd::pair_first_contact(motion, a, b, t0, t1))
        std::cout << a << " and " << b << " touch at t = " << *toi << "\n";
  std::cout << events.size() << " contact events in " << scene.horizon << " s\n";
  return 0;
}
// ---- README example ends ----
#undef main

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
