#pragma once
// The options and counters of the ground truth (ccd/truth/truth.hpp): one set for every
// kind of scene (spheres, rigid shapes, scenery, wrap-around).
#include <atomic>
#include <cstddef>
#include <functional>

namespace ccd {

class TruthTable;

struct TruthOptions {
  /// 0: one thread per hardware core (std::thread::hardware_concurrency()).
  static constexpr unsigned default_threads = 0;
  /// 0: automatic, ceil(0.5 * mean path extent / mean diameter) windows (a body's box
  /// grows by about two diameters per window; more windows cost more box work than the
  /// few candidate pairs they save, measured on gas scenes).
  static constexpr std::size_t default_windows = 0;
  /// Upper limit of the automatic window count.
  static constexpr std::size_t max_auto_windows = 64;
  unsigned threads = default_threads;
  std::size_t windows = default_windows;
  /// Certified brackets (shapes other than spheres): seconds; 0: 2^-30 x horizon (about
  /// 1e-9 of it). Pieces of time narrower than this that neither separation nor overlap
  /// can claim stay unresolved.
  double time_tolerance = 0.0;
  /// Certified brackets: distance evaluations allowed per (pair, run of windows); past it
  /// the rest of the run is left unresolved.
  std::size_t max_evaluations = 1000000;
  /// The solver per pair of shape kinds (ccd/truth/truth_table.hpp); nullptr: the default
  /// table (sphere x sphere and sphere x polygon exact, the rest certified brackets).
  const TruthTable* table = nullptr;
  /// Called as the solving advances (candidate runs solved, of all of them), from any of
  /// the worker threads, one call at a time; may be empty.
  std::function<void(std::size_t done, std::size_t total)> progress;
  /// Checked before every (pair, run of windows); when set, the truth stops and says so
  /// (TruthStats::cancelled). May be null.
  const std::atomic<bool>* cancel = nullptr;
};

/// Counters for the summary and for tuning.
struct TruthStats {
  std::size_t windows = 0;
  unsigned threads = 0;
  std::size_t candidate_pair_windows = 0;    ///< body-body box overlaps found by the candidate finder
  std::size_t candidate_runs = 0;            ///< (pair, consecutive windows) solved
  std::size_t static_candidate_runs = 0;     ///< (body, polygon, consecutive windows) solved
  std::size_t pairs_in_contact = 0;          ///< distinct pairs with at least one event
  std::size_t evaluations = 0;               ///< distance evaluations of the bracket search
  std::size_t grazing = 0;                   ///< body-body events flagged grazing
  std::size_t static_grazing = 0;            ///< static events flagged grazing
  std::size_t undecided = 0;                 ///< body-body events flagged undecided
  std::size_t static_undecided = 0;          ///< static events flagged undecided
  bool cancelled = false;                    ///< stopped by TruthOptions::cancel: the events are partial
};

}  // namespace ccd
