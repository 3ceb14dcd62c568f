// The compiled core of the `ferrodyn` Python package (ferrodyn/__init__.py documents the API).
#include "common.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "ferrodyn: railway vehicle dynamics with a research-grade wheel-rail contact layer";
  m.attr("__version__") = FERRO_VERSION;
  ferro::python::bind_scene(m);
  ferro::python::bind_run(m);
  auto analysis = m.def_submodule("analysis", "Stability and critical-speed analyses of scenes");
  ferro::python::bind_analysis(analysis);
  auto contact = m.def_submodule("contact", "Wheel-rail contact models on arrays of cases");
  ferro::python::bind_contact(contact);
  ferro::python::bind_output(m);
}
