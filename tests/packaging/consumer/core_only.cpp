// Uses only ccdlab::core: two spheres built in code, their exact contact interval.
#include <ccd/motion/trajectory.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <iostream>

int main() {
  ccd::Scene scene;
  scene.horizon = 2.0;
  ccd::Body a;
  a.radius = 0.5;
  a.position = ccd::Vec3(-2, 0, 0);
  a.velocity = ccd::Vec3(1, 0, 0);
  ccd::Body b = a;
  b.position = ccd::Vec3(2, 0, 0);
  b.velocity = ccd::Vec3(-1, 0, 0);
  scene.bodies = {a, b};
  const auto events = ccd::compute_truth(ccd::Trajectories(scene));
  // The centres close at 2 m/s from 4 m apart and touch at distance 1: t = 1.5.
  if (events.size() != 1 || events[0].enter != 1.5) return 1;
  std::cout << "enter " << events[0].enter << " exit " << events[0].exit << "\n";
  return 0;
}
