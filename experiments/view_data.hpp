#pragma once
// What the viewer page (`ccdlab view`, viewer/) is given: a scene's motion as the pieces of
// its exact trajectories, and optionally the ground truth and the records of a results file,
// each with the volumes its bound tested (experiments/view_volumes.hpp; docs/viewer.md). The page evaluates p + v s + a s^2 / 2 on the piece that holds t (and
// the rotation pieces of spinning shapes): the pieces come from ccd::Trajectories and
// ccd::Rotations, so the page draws the motion the truth and the methods saw, without
// frame dumps (a 10,000-body scene is a few pieces per body).
//
// Numbers are written with 9 significant digits (ample for drawing; the pieces' exact
// values stay in the C++ model). Inputs are checked: a results or truth file of another
// scene (its scene digest differs), a malformed `missed_events` or `static_missed_events`
// entry (a body or scenery polygon the scene lacks), or a cloth frames file with an index
// out of range throws ccd::InputError naming the file and the field. The scene's static
// scenery (polygons and mesh triangles) goes to the page as `scenery`, the truth's
// body-scenery events as `static_truth`.
#include <ccd/scene/scene.hpp>
#include <ccd/truth/truth_io.hpp>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace ccdlab {

inline constexpr const char* kViewDataFormat = "ccdlab-view/1";

struct ViewInputs {
  std::string scene_file;                 ///< named in the page and in errors
  std::string results_file;               ///< empty: none
  std::string truth_file;                 ///< empty: none
  std::optional<nlohmann::json> results;  ///< a parsed ccdlab-results/2 document
  std::optional<ccd::TruthFile> truth;
  bool force = false;  ///< build a page past kMaxViewEntries (experiments/work_estimate.hpp)
};

/// The page entries (trajectory pieces and sampled rotation pieces) `ccdlab view` writes
/// without --force: each is about 150 bytes of page, so the limit is about 750 MB.
inline constexpr double kMaxViewEntries = 5e6;

/// `x` with 9 significant digits (what a float, the GPU's precision, can show; short JSON).
double view_number(double x);

/// The page's data for a body scene (`ccdlab-scene/1` or `/2`). Throws ccd::InputError
/// (see the header comment; also when the page would hold more than kMaxViewEntries
/// entries and `inputs.force` is false) and ccd::TooManyPieces.
nlohmann::json body_view_data(const ccd::Scene& scene, const ViewInputs& inputs);

/// The page's data for the frames a cloth run wrote (`ccdlab-cloth-frames/1`, from
/// `ccdlab cloth ... -o FRAMES.json`): the mesh at each frame, drawn linearly in between.
/// Throws ccd::InputError naming `file` and the field, also when the page would hold more
/// than kMaxViewEntries particle positions (frames x particles) and `force` is false.
nlohmann::json cloth_view_data(const nlohmann::json& frames, const std::string& file, bool force = false);

}  // namespace ccdlab
