#pragma once
// The ground truth of a scene as one library call: every contact interval of every pair of
// bodies and, with scenery, of every body with every static polygon, with the certified
// error of each time (docs/truth.md).
//
//   const ccd::Trajectories traj(scene);
//   const ccd::RigidMotion motion(scene, traj);
//   ccd::Truth truth = ccd::compute_truth(motion, scene.scenery, options);
//   truth.scene_sha256 = ccd::scene_digest(scene);  // the caller holds the scene
//
// Inside: the candidate finder (ccd/truth/truth_candidates.hpp) gives the (pair, run of
// windows) and (body, polygon, run of windows) that may touch; each is solved by the
// entry of the truth table for its shape kinds (ccd/truth/truth_table.hpp: sphere x
// sphere and sphere x polygon exact, every other pair certified brackets). Runs go to
// threads in chunks (progress after each chunk, the cancel flag before each run); the
// events are then sorted by (enter, a, b) and (enter, body, polygon). The result does not
// depend on the thread count.
//
// `motion` is the scene's motion: centres (its Trajectories), shape kinds and proxies,
// rotations (empty for a scene of spheres; RigidMotion(traj) for plain trajectories).
// `scenery` is the scene's static polygons (empty: no static events, has_scenery false).
// The result's errors (static_errors) are empty when every event is exact; its digest is
// empty (set it from the scene); stats.cancelled says the run was stopped by
// options.cancel (the events are then partial).
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scenery.hpp>
#include <ccd/truth/truth_io.hpp>
#include <ccd/truth/truth_options.hpp>

#include <span>

namespace ccd {

Truth compute_truth(const RigidMotion& motion, std::span<const StaticPolygon> scenery, const TruthOptions& options = {});

}  // namespace ccd
