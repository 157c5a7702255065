// ccdlab.mesh_ccd: mesh CCD between two frames (cloth/mesh_ccd/mesh_ccd.hpp) on numpy
// arrays, returning the dict that `ccdlab ccd FRAME0 FRAME1 -o OUT.json` writes (without
// the frame files, the reading time and the peak memory). The GIL is released while it runs.
#include "bindings.hpp"

#include <cloth/mesh_ccd/mesh_ccd.hpp>
#include <cloth/mesh_ccd/mesh_ccd_json.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/parallel_for.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace ccdlab::python {

namespace {

constexpr const char* kWho = "ccdlab.mesh_ccd";

using Positions = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<ccd::Vec3> positions(const Positions& a, const char* name) {
  if (a.ndim() != 2 || a.shape(1) != 3) throw ccd::InputError(kWho, name, "must be an (n, 3) array of positions");
  std::vector<ccd::Vec3> out(static_cast<std::size_t>(a.shape(0)));
  const double* d = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = ccd::Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
    if (!out[i].allFinite()) throw ccd::InputError(kWho, std::string(name) + "[" + std::to_string(i) + "]", "coordinate not finite");
  }
  return out;
}

std::vector<std::array<std::uint32_t, 3>> faces(const py::array& f, std::size_t vertices) {
  if (f.ndim() != 2 || f.shape(1) != 3) throw ccd::InputError(kWho, "F", "must be an (m, 3) array of vertex indices");
  if (f.size() > 0 && !py::isinstance<py::array_t<std::int64_t>>(f) && f.dtype().kind() != 'i' &&
      f.dtype().kind() != 'u')
    throw ccd::InputError(kWho, "F", "must hold integers");
  const auto as64 = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(f);
  std::vector<std::array<std::uint32_t, 3>> out(static_cast<std::size_t>(f.shape(0)));
  const std::int64_t* d = as64.data();
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t v = d[3 * i + k];
      if (v < 0 || static_cast<std::uint64_t>(v) >= vertices)
        throw ccd::InputError(kWho, "F[" + std::to_string(i) + "]",
                              "vertex index " + std::to_string(v) + " out of range (" + std::to_string(vertices) + " vertices)");
      out[i][k] = static_cast<std::uint32_t>(v);
      for (std::size_t j = 0; j < k; ++j)
        if (out[i][j] == out[i][k])
          throw ccd::InputError(kWho, "F[" + std::to_string(i) + "]", "vertex " + std::to_string(v) + " repeated");
    }
  return out;
}

py::object mesh_ccd(const Positions& v0, const Positions& v1, const py::array& f, double separation,
                    const std::string& cull, unsigned threads, bool exact) {
  const std::vector<ccd::Vec3> x0 = positions(v0, "V0"), x1 = positions(v1, "V1");
  if (x0.size() != x1.size())
    throw ccd::InputError(kWho, "V1", "has " + std::to_string(x1.size()) + " vertices, V0 has " + std::to_string(x0.size()));
  const auto fs = faces(f, x0.size());
  ccd::cloth::MeshCcdOptions o;
  o.separation = separation;
  o.culler = cull;
  o.threads = threads;
  o.exact = exact;
  ccd::cloth::MeshCcdResult r;
  {
    py::gil_scoped_release release;
    try {
      r = ccd::cloth::mesh_ccd(x0, x1, fs, o);
    } catch (const std::invalid_argument& e) {
      throw ccd::InputError(kWho, "", e.what());
    }
  }
  return to_python(ccd::cloth::mesh_ccd_json(r, o, ccd::resolve_threads(threads)));
}

}  // namespace

void bind_mesh_ccd(py::module_& m) {
  m.def("mesh_ccd", &mesh_ccd, py::arg("V0"), py::arg("V1"), py::arg("F"), py::arg("separation") = 0.0,
        py::arg("cull") = "mesh_sweep", py::arg("threads") = 0u, py::arg("exact") = false,
        "Mesh CCD between two frames: V0, V1 (n, 3) positions at t = 0 and t = 1 (each vertex moves "
        "linearly), F (m, 3) vertex indices. Returns the ccdlab-mesh-ccd/1 dict of `ccdlab ccd FRAME0 "
        "FRAME1`: candidates, collisions {vf: [[v, f]], ee: [[a0, a1, b0, b1]]}, toi, seconds. Bad input "
        "raises ccdlab.InputError.");
}

}  // namespace ccdlab::python
