#pragma once
// Reading and writing `ccdlab-truth/1` files: the exact contact intervals of a scene
// (docs/truth.md describes every field).
//
//   {"format": "ccdlab-truth/1", "horizon": T,
//    "events": [{"a": i, "b": j, "enter": t0, "exit": t1}, ...]}
//
// Times are written with 17 significant digits, so a file round-trips bit for bit.
// Validation on reading: malformed JSON, a missing or mistyped field, a non-finite
// number, horizon <= 0, a or b not a non-negative integer, a >= b, enter > exit, times
// outside [0, horizon], events out of (enter, a, b) order: each throws InputError naming
// the file and the field (`events[3].exit`). Unknown fields are ignored.
#include <ccd/truth/ground_truth.hpp>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ccd {

struct TruthFile {
  double horizon = 0.0;
  std::vector<ContactEvent> events;  ///< sorted by (enter, a, b)
};

inline constexpr const char* kTruthFormat = "ccdlab-truth/1";

nlohmann::json truth_to_json(const TruthFile& truth);
/// Text of the file: one event per line, for diff-friendly output.
std::string truth_to_text(const TruthFile& truth);
/// Parses and validates; `file` is used only in error messages. Throws InputError.
TruthFile truth_from_json(const nlohmann::json& j, const std::string& file);
/// Reads and validates a truth file. Throws InputError.
TruthFile load_truth(const std::string& path);
/// Writes atomically (ccd/io/atomic_file.hpp).
void save_truth(const TruthFile& truth, const std::string& path);

}  // namespace ccd
