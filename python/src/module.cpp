// maze_mapper._native: the C++ parts of the Python package `maze_mapper` (python/maze_mapper/
// is the Python side). A bad input raises maze_mapper.Error with the line the program prints
// ("FILE:LINE:COL: error: ..." or "error: ..."); a failure the program reports with exit
// status 1 raises RuntimeError with its "error: ..." line.

#include <exception>
#include <string>

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "kept_map.hpp"
#include "common/error.hpp"

PYBIND11_MODULE(_native, m) {
  namespace py = pybind11;
  m.doc() = "maze_mapper's grid, models, renderer, scorer and embedded simulator";
  static py::exception<common::InputError> error(m, "Error", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const common::InputError &e) {
      PyErr_SetString(error.ptr(), e.diagnostic().c_str());
    } catch (const common::RuntimeFailure &e) {
      PyErr_SetString(PyExc_RuntimeError, (std::string("error: ") + e.what()).c_str());
    }
  });
  maze_mapper_python::bind_mapping(m);
  maze_mapper_python::bind_models(m);
  maze_mapper_python::bind_render(m);
  maze_mapper_python::bind_world(m);
  maze_mapper_python::bind_kept_map(m);
  maze_mapper_python::bind_run_files(m);
  maze_mapper_python::bind_simulator(m);
}
