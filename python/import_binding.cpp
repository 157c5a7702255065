// ccdlab.import_frames: recorded frames of a simulation as numpy arrays to a scene, through
// the reader of `ccdlab import` (ccd/scene/recorded_frames.hpp): the arrays are written as
// its CSV (every double in its shortest exact text) and read back, so the scene is the one
// `ccdlab import` makes of the same numbers.
#include "bindings.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/recorded_frames.hpp>

#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace ccdlab::python {

namespace {

constexpr const char* kWho = "ccdlab.import_frames";
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

void put(std::string& out, double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

/// The CSV text of frames: one row per (frame, body).
std::string frames_csv(const Array& positions, const Array& times, const std::optional<Array>& radii) {
  if (positions.ndim() != 3 || positions.shape(2) != 3)
    throw ccd::InputError(kWho, "positions", "must be a (frames, bodies, 3) array");
  const auto frames = static_cast<std::size_t>(positions.shape(0));
  const auto bodies = static_cast<std::size_t>(positions.shape(1));
  if (times.ndim() != 1 || static_cast<std::size_t>(times.shape(0)) != frames)
    throw ccd::InputError(kWho, "times", "must be a (frames,) array, one time per frame of positions");
  if (radii && (radii->ndim() != 1 || static_cast<std::size_t>(radii->shape(0)) != bodies))
    throw ccd::InputError(kWho, "radii", "must be a (bodies,) array, one radius per body of positions");
  const double* p = positions.data();
  const double* t = times.data();
  for (std::size_t i = 0; i < frames * bodies * 3; ++i)
    if (!std::isfinite(p[i]))
      throw ccd::InputError(kWho, "positions[" + std::to_string(i / (3 * bodies)) + ", " +
                                      std::to_string(i / 3 % bodies) + ", " + std::to_string(i % 3) + "]",
                            "not a finite number");
  std::string csv = radii ? "body,t,x,y,z,radius\n" : "body,t,x,y,z\n";
  csv.reserve(csv.size() + frames * bodies * 64);
  for (std::size_t f = 0; f < frames; ++f)
    for (std::size_t b = 0; b < bodies; ++b) {
      csv += std::to_string(b);
      csv += ',';
      put(csv, t[f]);
      for (std::size_t k = 0; k < 3; ++k) {
        csv += ',';
        put(csv, p[(f * bodies + b) * 3 + k]);
      }
      if (radii) {
        csv += ',';
        put(csv, radii->data()[b]);
      }
      csv += '\n';
    }
  return csv;
}

}  // namespace

void bind_import(py::module_& m) {
  m.def(
      "import_frames",
      [](const Array& positions, const Array& times, std::optional<Array> radii, std::optional<double> radius) {
        if (radii.has_value() == radius.has_value())
          throw ccd::InputError(kWho, "radii", "give radii (one per body) or radius (every body), not both or neither");
        const std::string csv = frames_csv(positions, times, radii);
        ccd::FrameImportOptions options;
        options.radius = radius;
        std::istringstream in(csv);
        ccd::FrameImport imported = [&] {
          py::gil_scoped_release release;
          return ccd::import_frames(in, "frames", options);
        }();
        return std::make_shared<PyScene>(std::move(imported.scene), kWho);
      },
      py::arg("positions"), py::arg("times"), py::kw_only(), py::arg("radii") = py::none(),
      py::arg("radius") = py::none(),
      "The scene of recorded frames, as `ccdlab import` makes it (docs/import.md): positions a "
      "(frames, bodies, 3) array of centres, times (frames,) in s, and radii (bodies,) or one radius. "
      "Between frames each centre moves linearly; time 0 is the first frame. Errors name the array "
      "and index, or the frame row (`frames: line 7: ...`, line = 2 + frame x bodies + body).");
}

}  // namespace ccdlab::python
