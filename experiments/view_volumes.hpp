#pragma once
// The volumes a run's bound tested (Bound::volumes, bounds/volume.hpp), for the viewer page
// (`ccdlab view`, docs/viewer.md): the page draws these and computes no bound of its own.
//
// For a run of a results file (its method and dt), each body's windows are those the run
// built its bound over: the fixed steps [k dt, (k+1) dt] (an instant bound at k dt), or for
// an `@earliest` method each body's own windows (pipeline/window_policy.hpp: dt, or
// speed-adapted with `reach`, aligned or not), each built from the body's state at its
// start by Bound::refresh as the scheduler builds it. Not shown: the scheduler's refined
// bounds of a pair (built from a check time on, and with `refresh_bodies` the body
// windows they start).
//
// Page size: every window of every body of every run is exported when that is at most
// kMaxViewVolumes volumes in all; otherwise, per run, only the windows that hold the middle
// of each listed missed contact, for its two bodies (what the page jumps to), until that
// budget is spent. Runs of a scene that wraps around, or whose method this build does not
// know, get none (with the reason).
#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/scene.hpp>

#include <nlohmann/json.hpp>

namespace ccdlab {

/// The most volumes one page holds (about 100 to 250 bytes each in the page).
inline constexpr double kMaxViewVolumes = 2e5;

/// Adds "volumes" to every run of `runs` (the page's runs, experiments/view_data.hpp: each
/// with "method", "dt", "acceleration_bound" and optionally "missed_events"):
///   {"coverage": "all" | "missed" | "none", "reason": text (when not "all"),
///    "bodies": [per body: [[w0, w1, [volume, ...]], ...] in time order]}
/// with each volume {"kind": "box" | "sphere" | "capsule" | "oriented_box", "t": [t0, t1],
/// box: "lo", "hi"; sphere: "c", "r"; capsule: "a", "b", "r"; oriented_box: "c", "axes"
/// (the three unit axes, one after the other), "half"}. Times are written in full, lengths
/// with 9 significant digits (view_number). `traj` is `scene`'s motion.
void add_run_volumes(const ccd::Scene& scene, const ccd::Trajectories& traj, nlohmann::json& runs);

}  // namespace ccdlab
