// Single CCD queries on numpy arrays: vertex_face_ccd and edge_edge_ccd (the conservative
// triangle kernel, cloth/ccd/triangle_ccd.hpp), one query or a batch, and sphere_sphere_toi
// (the exact solver of the ground truth, ccd/queries/sphere_sphere_contact.hpp).
#include "bindings.hpp"

#include <cloth/ccd/triangle_ccd.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/queries/sphere_sphere_contact.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace ccdlab::python {

namespace {

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// (4, 3) -> 1 query, (k, 4, 3) -> k queries; the number of queries.
std::size_t query_count(const std::string& who, const char* name, const Points& a) {
  const bool one = a.ndim() == 2 && a.shape(0) == 4 && a.shape(1) == 3;
  const bool many = a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 3;
  if (!one && !many) throw ccd::InputError(who, name, "must be a (4, 3) array of points, or (k, 4, 3)");
  return one ? 1 : static_cast<std::size_t>(a.shape(0));
}

ccd::cloth::TriangleCcdOptions kernel_options(const std::string& who, double separation, double tolerance,
                                              std::uint32_t max_boxes) {
  if (!(separation >= 0.0 && std::isfinite(separation))) throw ccd::InputError(who, "separation", "must be finite and >= 0");
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw ccd::InputError(who, "tolerance", "must be in (0, 1)");
  if (max_boxes == 0) throw ccd::InputError(who, "max_boxes", "must be > 0");
  return {separation, tolerance, max_boxes};
}

py::dict one_result(const ccd::cloth::TriangleCcdResult& r) {
  const bool hit = r.status != ccd::QueryStatus::Miss;
  py::dict d;
  d["status"] = std::string(ccd::to_string(r.status));
  d["hit"] = hit;
  d["toi"] = hit && std::isfinite(r.toi) ? py::object(py::float_(r.toi)) : py::none();
  d["toi_upper"] = std::isfinite(r.toi_upper) ? py::object(py::float_(r.toi_upper)) : py::none();
  d["toi_error"] = std::isfinite(r.toi_upper) ? py::object(py::float_(r.toi_upper - r.toi)) : py::none();
  d["boxes"] = r.boxes;
  d["budget_spent"] = r.budget_spent;
  return d;
}

/// The kernel on every query of (start, end); one query gives a dict, a batch a dict of arrays.
py::dict triangle_queries(ccd::cloth::PrimitivePair kind, const Points& start, const Points& end,
                          double separation, double tolerance, std::uint32_t max_boxes) {
  const std::string who =
      kind == ccd::cloth::PrimitivePair::VertexFace ? "ccdlab.vertex_face_ccd" : "ccdlab.edge_edge_ccd";
  const std::size_t k = query_count(who, "start", start);
  if (query_count(who, "end", end) != k || start.ndim() != end.ndim())
    throw ccd::InputError(who, "end", "must have the shape of start");
  const auto options = kernel_options(who, separation, tolerance, max_boxes);
  const double* s = start.data();
  const double* e = end.data();
  std::vector<ccd::cloth::TriangleCcdResult> results(k);
  {
    py::gil_scoped_release release;
    for (std::size_t q = 0; q < k; ++q) {
      ccd::cloth::LinearQuery query;
      for (std::size_t i = 0; i < 4; ++i) {
        const double* a = s + 12 * q + 3 * i;
        const double* b = e + 12 * q + 3 * i;
        query.x[i] = ccd::Vec3(a[0], a[1], a[2]);
        query.x[i + 4] = ccd::Vec3(b[0], b[1], b[2]);
      }
      results[q] = ccd::cloth::triangle_ccd(kind, query, options);
    }
  }
  if (start.ndim() == 2) return one_result(results[0]);
  std::vector<bool> hit(k);
  std::vector<double> toi(k), toi_error(k);
  std::vector<std::uint32_t> boxes(k);
  for (std::size_t q = 0; q < k; ++q) {
    const auto& r = results[q];
    hit[q] = r.status != ccd::QueryStatus::Miss;
    toi[q] = hit[q] ? r.toi : std::nan("");
    toi_error[q] = std::isfinite(r.toi_upper) ? r.toi_upper - r.toi : std::nan("");
    boxes[q] = r.boxes;
  }
  py::array_t<bool> hits(static_cast<py::ssize_t>(k));
  for (std::size_t q = 0; q < k; ++q) hits.mutable_data()[q] = hit[q];
  py::dict d;
  d["hit"] = hits;
  d["toi"] = owning_array(std::move(toi), {static_cast<py::ssize_t>(k)});
  d["toi_error"] = owning_array(std::move(toi_error), {static_cast<py::ssize_t>(k)});
  d["boxes"] = owning_array(std::move(boxes), {static_cast<py::ssize_t>(k)});
  return d;
}

ccd::Vec3 vec3(const std::string& who, const char* name, const Points& a) {
  if (a.ndim() != 1 || a.shape(0) != 3) throw ccd::InputError(who, name, "must be 3 numbers");
  const ccd::Vec3 v(a.data()[0], a.data()[1], a.data()[2]);
  if (!v.allFinite()) throw ccd::InputError(who, name, "must be finite");
  return v;
}

py::dict sphere_sphere(const Points& pa, const Points& va, double ra, const Points& pb, const Points& vb, double rb,
                       double duration, const std::optional<Points>& aa, const std::optional<Points>& ab) {
  const std::string who = "ccdlab.sphere_sphere_toi";
  const ccd::Vec3 zero = ccd::Vec3::Zero();
  ccd::MovingSphere a{vec3(who, "position_a", pa), vec3(who, "velocity_a", va),
                      aa ? vec3(who, "acceleration_a", *aa) : zero, ra};
  ccd::MovingSphere b{vec3(who, "position_b", pb), vec3(who, "velocity_b", vb),
                      ab ? vec3(who, "acceleration_b", *ab) : zero, rb};
  if (!(ra > 0.0 && std::isfinite(ra))) throw ccd::InputError(who, "radius_a", "must be finite and > 0");
  if (!(rb > 0.0 && std::isfinite(rb))) throw ccd::InputError(who, "radius_b", "must be finite and > 0");
  if (!(duration >= 0.0 && std::isfinite(duration))) throw ccd::InputError(who, "duration", "must be finite and >= 0");
  const ccd::SphereSphereContact first = ccd::sphere_sphere_first_contact(a, b, duration);
  const ccd::SublevelSet intervals = ccd::sphere_sphere_contact_intervals(a, b, duration);
  py::list spans;
  for (int i = 0; i < intervals.count; ++i) {
    const ccd::RootInterval& span = intervals.intervals[static_cast<std::size_t>(i)];
    spans.append(py::make_tuple(span.lo, span.hi));
  }
  py::dict d;
  d["status"] = std::string(ccd::to_string(first.status));
  d["hit"] = first.status == ccd::QueryStatus::Hit || first.status == ccd::QueryStatus::Overlapping;
  d["toi"] = std::isfinite(first.toi) ? py::object(py::float_(first.toi)) : py::none();
  d["toi_error"] = 0.0;  // exact: the ground truth's solver (signs certified, roots to adjacent doubles)
  d["intervals"] = spans;
  return d;
}

}  // namespace

void bind_queries(py::module_& m) {
  const auto doc_kernel =
      "the conservative kernel (never a false negative): start and end are the four points at t = 0 and "
      "t = 1, a (4, 3) array (one query: a dict with status, hit, toi (a lower bound of the first "
      "contact, None on a miss), toi_upper, toi_error (toi_upper - toi: a contact is proved by "
      "toi_upper; None when no time is certified), boxes, budget_spent) or (k, 4, 3) (a batch: a dict "
      "of arrays hit, toi, toi_error, boxes; NaN where undefined)";
  m.def(
      "vertex_face_ccd",
      [](const Points& start, const Points& end, double separation, double tolerance, std::uint32_t max_boxes) {
        return triangle_queries(ccd::cloth::PrimitivePair::VertexFace, start, end, separation, tolerance, max_boxes);
      },
      py::arg("start"), py::arg("end"), py::kw_only(), py::arg("separation") = 0.0, py::arg("tolerance") = 1e-9,
      py::arg("max_boxes") = 20000,
      (std::string("Vertex-face CCD over t in [0, 1], rows vertex, face corner 0, 1, 2: ") + doc_kernel).c_str());
  m.def(
      "edge_edge_ccd",
      [](const Points& start, const Points& end, double separation, double tolerance, std::uint32_t max_boxes) {
        return triangle_queries(ccd::cloth::PrimitivePair::EdgeEdge, start, end, separation, tolerance, max_boxes);
      },
      py::arg("start"), py::arg("end"), py::kw_only(), py::arg("separation") = 0.0, py::arg("tolerance") = 1e-9,
      py::arg("max_boxes") = 20000,
      (std::string("Edge-edge CCD over t in [0, 1], rows edge a's two ends, edge b's two ends: ") + doc_kernel)
          .c_str());
  m.def("sphere_sphere_toi", &sphere_sphere, py::arg("position_a"), py::arg("velocity_a"), py::arg("radius_a"),
        py::arg("position_b"), py::arg("velocity_b"), py::arg("radius_b"), py::arg("duration"), py::kw_only(),
        py::arg("acceleration_a") = py::none(), py::arg("acceleration_b") = py::none(),
        "First contact of two spheres moving as p + v s + a s^2/2 over s in [0, duration], exact (the "
        "ground truth's solver): a dict with status (hit, overlapping, miss), hit, toi (None on a miss), "
        "toi_error (0: exact) and intervals (every contact interval (enter, exit), touching included)");
}

}  // namespace ccdlab::python
