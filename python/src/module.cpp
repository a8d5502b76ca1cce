// The extension module parashade._parashade (docs/python.md); python/parashade/__init__.py is its face.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "parashade/version.hpp"

PYBIND11_MODULE(_parashade, m) {
  namespace py = pybind11;
  m.doc() = "parashade's render step and commands; use the package parashade, not this module";
  m.attr("version") = parashade::version;
  m.attr("git_hash") = parashade::git_hash;
  m.def("render", &parashade::python::render, py::arg("words"), py::arg("kept_key"));
  m.def("scene_info", &parashade::python::scene_info, py::arg("path"), py::arg("size"));
  m.def("run_command", &parashade::python::run_command, py::arg("words"));
  m.def("clear_cache", &parashade::python::clear_cache);
  parashade::python::register_error_translation();
}
