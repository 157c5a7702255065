#pragma once
// Recorded motion in, a scene out: the reader behind `ccdlab import` (docs/import.md).
//
// Input: CSV text with a header row naming the columns, in any order:
//   body,t,x,y,z           required: a body label, the time (s) and the centre (m)
//   radius                 the body's radius (m), > 0, the same in every row of the body
//   shape                  a shape's name (from FrameImportOptions::shapes) or an inline
//                          shape `sphere:R`, `capsule:HALF_LENGTH,R`, `box:HX,HY,HZ`
//   qw,qx,qy,qz            all four or none: the orientation (unit quaternion, body to
//                          world, accepted within 1e-6 of unit length and normalised)
// A row gives its body's size as a radius or a shape (an empty cell is not given; with
// neither, FrameImportOptions::radius). Rows may come in any order; blank lines are
// skipped; cells are trimmed of spaces; a cell in double quotes may hold commas
// (`"box:1,0.5,0.25"`, as Python's csv module writes it; "" inside is a quote).
//
// The model: between two frames of a body its centre moves linearly (a velocity change at
// every frame) and, for a shaped body with orientation columns, it turns at the constant
// world-frame angular velocity that takes one frame's orientation to the next by the
// shortest arc. The scene's time 0 is the earliest time in the file and its horizon the
// latest time minus the earliest; every body must have a frame at both (a body that
// appears late or leaves early is refused: the scene format has no such body). Bodies'
// frame times may differ. Each velocity is computed from the model's own position at the
// frame (tracked in double-double as the trajectory does), so rounding does not build up
// from frame to frame; a velocity change equal to the velocity before it is left out.
// Plain spheres ignore the orientation columns (checked, not used). The scene has no
// walls and no gravity: the recording already holds them.
//
// Body order: by label, numerically when every label is a non-negative integer (so
// `ccdlab poses` output comes back in its order), as strings otherwise.
//
// Errors: InputError naming the file, the line and the column
// (`frames.csv: line 7: radius: must be > 0`): a missing header column, an unknown
// column, a row with the wrong number of cells, a cell that is not a finite number, a
// body's second frame at the same time, a radius <= 0 or changing within a body, a
// changing shape, an unknown shape, a quaternion further than 1e-6 from unit length, a
// body without a frame at the first or the last time (named at the first line where the
// body's time goes backwards, if it does), fewer than two distinct times.
// The resulting scene is validated as any scene (ccd/scene/scene_io.hpp).
#include <ccd/scene/scene.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace ccd {

struct FrameImportOptions {
  /// Radius (m) of the bodies whose rows give neither a radius nor a shape (the output of
  /// `ccdlab poses` has no size columns); none: such a row is an error.
  std::optional<double> radius;
  /// Named shapes, as the `shapes` array of a `ccdlab-scene/2` file (docs/formats.md).
  nlohmann::json shapes = nlohmann::json::array();
  /// Names `shapes` in error messages (`shapes.json: shapes[1].half_extents[2]: must be > 0`).
  std::string shapes_file = "--shapes";
};

struct FrameImport {
  Scene scene;
  double time_origin = 0.0;          ///< the file's earliest time (scene time 0)
  std::size_t frames = 0;            ///< rows read
  std::vector<std::string> labels;   ///< the body labels, index for index with the scene's bodies
};

/// Reads recorded frames (CSV text) and builds the scene. `file` names the input in
/// error messages. Throws InputError.
FrameImport import_frames(std::istream& csv, const std::string& file, const FrameImportOptions& options = {});

}  // namespace ccd
