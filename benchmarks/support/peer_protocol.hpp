#pragma once
// The peers' timing protocol on the shared moving-spheres scene (benchmarks/support/peer_scene.hpp):
// frame 0 builds the structure (not timed), frames 1 and 2 are warm-up, frames 3..22 are
// measured; a frame's time is BroadPhase::find_pairs alone (the structure's update and the
// query), not the scene's motion or the box computation. The figure is the median.
// Both the thread's CPU time and wall-clock time are recorded: on an idle machine they agree,
// on a shared one (this 2-core machine runs other jobs) the CPU time is the one that does
// not count other processes' time slices.
#include <ccd/broad_phase/broad_phase.hpp>

#include <cstdint>
#include <string>

namespace ccdlab::bench {

struct PeerRun {
  double median_ms = 0.0;       ///< median thread CPU ms per measured frame
  double min_ms = 0.0;          ///< fastest measured frame, thread CPU ms
  double max_ms = 0.0;          ///< slowest frame of 1..22 (warm-up included), thread CPU ms
  double setup_ms = 0.0;        ///< frame 0 (build and first query), thread CPU ms
  double median_wall_ms = 0.0;  ///< median wall-clock ms per measured frame
  double pairs_per_frame = 0.0;  ///< mean over the measured frames
  double swaps_per_frame = 0.0;  ///< mean of the method's "swaps" counter (BroadPhase::counters) over the measured frames
  int rebuilds = 0;              ///< measured frames with BroadPhaseStats::rebuilt
  std::string error;             ///< non-empty when frame 0 or 22 differs from the published table
};

inline constexpr int kWarmupFrames = 2;
inline constexpr int kMeasuredFrames = 20;

/// Runs the protocol for `method` on the scene (n, seed 1); checks frames 0 and 22
/// against peer_scene_references() when n is in the table.
PeerRun run_peer_protocol(ccd::BroadPhase& method, std::size_t n);

/// Checks the scene's frame 0 and 22 pair counts and checksums for every tabulated N
/// up to `max_n` with `method` (a fast one); returns an error text or "".
std::string verify_peer_scene(ccd::BroadPhase& method, std::size_t max_n);

}  // namespace ccdlab::bench
