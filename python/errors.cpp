// Bad input as Python exceptions: ccd::InputError becomes ccdlab.InputError, a ValueError
// with the file and the field (`bodies[3].radius`) as attributes `.file` and `.field`.
#include "bindings.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

namespace ccdlab::python {

void bind_errors(py::module_& m) {
  static py::exception<ccd::InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input: a ValueError whose .file and .field name where (field '' when the whole input)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ccd::InputError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      instance.attr("file") = e.file();
      instance.attr("field") = e.field();
      PyErr_SetObject(input_error.ptr(), instance.ptr());
    }
  });
}

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(py::str(j.dump()));
}

nlohmann::json from_python(const py::handle& obj, const std::string& what) {
  // numpy scalars and arrays become numbers and lists; NaN and infinity are refused.
  const py::cpp_function plain([](py::object o) -> py::object {
    if (py::hasattr(o, "tolist")) return o.attr("tolist")();
    throw py::type_error("not JSON: " + py::repr(o).cast<std::string>());
  });
  std::string text;
  try {
    text = py::module_::import("json")
               .attr("dumps")(obj, py::arg("allow_nan") = false, py::arg("default") = plain)
               .cast<std::string>();
  } catch (const py::error_already_set& err) {
    // NaN, infinity, a complex number, a date: json's own message, naming the argument.
    if (!err.matches(PyExc_TypeError) && !err.matches(PyExc_ValueError)) throw;
    throw ccd::InputError(what, "", "not JSON: " + py::str(err.value()).cast<std::string>());
  }
  return ccd::parse_json_text(text, what);
}

}  // namespace ccdlab::python
