// Uses the installed package through ccdlab::ccdlab: a generated scene (the runner's
// generators), its exact truth, and one step of a conservative pipeline.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <generators/registry.hpp>
#include <iostream>

int main() {
  const ccd::Scene scene = ccdlab::generate_scene("gas", nlohmann::json{{"bodies", 200}, {"seed", 3}});
  const ccd::Trajectories motion(scene);
  const auto events = ccd::compute_truth(motion);
  const ccd::BoundSpec capsule = ccd::parse_bound("capsule");
  ccd::StepPipeline pipeline(capsule.make(), capsule.info->knowledge, ccd::find_broad_phase("grid").make());
  std::vector<ccd::BodyState> start;
  ccd::StateCursor(motion).evaluate(0.0, start);
  ccd::StepResult step;
  const ccd::RigidMotion scene_motion(scene, motion);
  pipeline.run({.t0 = 0.0, .t1 = scene.horizon, .start = start, .exact = &motion, .walls = scene.box,
                .motion = &scene_motion},
               step);
  // Over one step covering the whole horizon, a conservative bound finds every pair of the truth.
  std::cout << "bodies " << scene.bodies.size() << " events " << events.size() << " contacts "
            << step.bodies.contacts.size() << "\n";
  return events.empty() || step.bodies.contacts.size() < 1 ? 1 : 0;
}
