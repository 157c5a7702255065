#pragma once
// The order in which `ccdlab run` starts its (method, dt) jobs: smallest dt first. A job's
// work is its step count times the bodies, so the smallest dt is the costliest; started
// first, the long jobs overlap and the short ones fill in at the end, so the threads
// finish together instead of one thread running the costliest job alone at the end.
// Only the start order changes: each job's record stays at its own place in the results.
#include <cstddef>
#include <span>
#include <vector>

namespace ccdlab {

/// A permutation of [0, dt.size()): job indices by dt ascending, equal dt in index order.
std::vector<std::size_t> job_order(std::span<const double> dt);

}  // namespace ccdlab
