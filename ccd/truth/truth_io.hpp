#pragma once
// Reading and writing truth files: the exact contact intervals of a scene (docs/truth.md
// describes every field). Written as `ccdlab-truth/2`; `ccdlab-truth/1` files (no scene
// digest, no error fields) are read too.
//
//   {"format": "ccdlab-truth/2", "horizon": T, "scene_sha256": "<64 hex digits>",
//    "events": [{"a": i, "b": j, "enter": t0, "exit": t1}, ...]}
//
// Per event, version 2 may add `enter_error` and `exit_error` (seconds >= 0: certified
// bounds on the error of enter and exit; absent = 0, exact) and `grazing` (true: the pair's
// distance stays within the solver's tolerance band, so the event may or may not exist;
// absent = false) and `undecided` (true: the truth could certify neither a contact in the
// event nor a separation through it; absent = the event's `grazing`, so in files written
// before the field existed every grazing event reads as undecided, which it was). They
// live in TruthFile::errors, a side table that stays empty when every event is exact, so
// ContactEvent keeps its size.
//
// Scenes with static scenery (docs/scenery.md) add, after `events`,
//   "static_events": [{"body": i, "polygon": j, "enter": t0, "exit": t1}, ...]
// (polygon = index in the scene's scenery, mesh triangles after the polygons), sorted by
// (enter, body, polygon); the field is absent for a scene without scenery, so such
// truth files are unchanged. A static event of a rigid body (certified, not exact) may
// carry `enter_error`, `exit_error`, `grazing` and `undecided` as body-body events do
// (TruthFile::static_errors).
// Times are written with 17 significant digits, so a file round-trips bit for bit.
// Validation on reading: malformed JSON, a missing or mistyped field, a non-finite
// number, horizon <= 0, a digest that is not 64 lowercase hex digits, a or b not a
// non-negative integer, a >= b, enter > exit, times outside [0, horizon], a negative
// error, events out of (enter, a, b) order: each throws InputError naming the file and
// the field (`events[3].exit`). Unknown fields are ignored.
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/static_truth.hpp>
#include <ccd/truth/truth_options.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

namespace ccd {

/// Accuracy of one event's times; all zero for an exact solver.
struct EventError {
  double enter_error = 0.0;  ///< seconds
  double exit_error = 0.0;   ///< seconds
  bool grazing = false;
  /// Neither a contact nor a separation could be certified: the event may or may not
  /// exist. Runners count it apart (never a miss). Every such event is grazing too.
  bool undecided = false;
  bool operator==(const EventError&) const = default;
};

/// The largest enter or exit error of `errors` (0 when there are none): how far a
/// certified event's times may be from the exact ones, the slack of matching against it.
inline double largest_error(std::span<const EventError> errors) {
  double e = 0.0;
  for (const EventError& x : errors) e = std::max({e, x.enter_error, x.exit_error});
  return e;
}

/// The ground truth of a scene: what compute_truth (ccd/truth/truth.hpp) returns and a
/// truth file holds (stats are not written: zero when read).
struct Truth {
  double horizon = 0.0;
  std::vector<ContactEvent> events;  ///< sorted by (enter, a, b)
  /// SHA-256 of the canonical scene (ccd/scene/scene_digest.hpp); empty when unknown
  /// (a version 1 file).
  std::string scene_sha256;
  /// One entry per event, or empty when every event is exact.
  std::vector<EventError> errors;
  /// The scene has scenery: `static_events` is written (possibly empty) and was read.
  bool has_scenery = false;
  /// Body-scenery events, sorted by (enter, body, polygon); empty without scenery.
  std::vector<StaticEvent> static_events;
  /// One entry per static event, or empty when every static event is exact (spheres).
  std::vector<EventError> static_errors;
  int version = 2;  ///< the format version read (written files are version 2)
  TruthStats stats;  ///< how it was computed (compute_truth); not part of the file
};

/// The same struct under its earlier name.
using TruthFile = Truth;

inline constexpr const char* kTruthFormat = "ccdlab-truth/2";
inline constexpr const char* kTruthFormatV1 = "ccdlab-truth/1";

nlohmann::json truth_to_json(const TruthFile& truth);
/// Text of the file: one event per line, for diff-friendly output.
std::string truth_to_text(const TruthFile& truth);
/// Parses and validates; `file` is used only in error messages. Throws InputError.
TruthFile truth_from_json(const nlohmann::json& j, const std::string& file);
/// Reads and validates a truth file. Throws InputError.
TruthFile load_truth(const std::string& path);
/// Writes atomically (ccd/io/atomic_file.hpp) as version 2.
void save_truth(const TruthFile& truth, const std::string& path);

}  // namespace ccd
