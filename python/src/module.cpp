// maze_mapper._native: the C++ parts of the Python package `maze_mapper` (python/maze_mapper/
// is the Python side). A bad input raises maze_mapper.Error with the line the program prints
// ("FILE:LINE:COL: error: ..." or "error: ..."); a failure the program reports with exit
// status 1 raises RuntimeError with its "error: ..." line, a full disk NoSpaceError (a
// RuntimeError; the program's exit status 4).

#include <exception>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "kept_map.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/standard_streams.hpp"

// The commands' handling of SIGINT, SIGTERM and SIGHUP (common/interrupt.hpp) for the Python
// runner (maze_mapper.run): the same handler, so that a signal while the controller runs stops
// the run at its next step and a signal while files are written removes their temporaries.
namespace maze_mapper_python {

namespace {

// `with SignalsStopWork():` a stop signal is recorded for the run to poll, not the process's end.
class StopWork {
 public:
  void enter() { guard_.emplace(); }
  void exit() { guard_.reset(); }

 private:
  std::optional<common::SignalsStopWork> guard_;
};

}  // namespace

void bind_signals(py::module_ &m) {
  m.def("secure_standard_streams", &common::secure_standard_streams,
        "Opens /dev/null on each of the file descriptors 0, 1, 2 that is closed, so that no file the run opens takes "
        "its number (a trace that became fd 1 would receive the printed summary).");
  m.def("install_signal_handlers", &common::install_signal_handlers,
        "SIGINT, SIGTERM and SIGHUP as the commands take them: the process ends (its unfinished output files "
        "removed, exit status 128 + the signal), or, inside SignalsStopWork, the signal is recorded.");
  m.def("interrupted", &common::interrupted, "Whether a stop signal has been recorded.");
  m.def("interrupt_name", &common::interrupt_name, "How a summary names the signal: Ctrl-C, SIGTERM, SIGHUP.");
  m.def("interrupted_exit_status", &common::interrupted_exit_status, "128 + the recorded signal.");
  m.def("forget_temporaries", &common::forget_temporaries,
        "In a forked child: the parent's unfinished output files are never the child's to remove.");
  m.attr("NO_SPACE_EXIT_STATUS") = common::kExitNoSpace;
  py::class_<StopWork>(m, "SignalsStopWork",
                       "While inside `with`: a stop signal is recorded (interrupted()) instead of ending the process.")
      .def(py::init<>())
      .def("__enter__", [](StopWork &w) -> StopWork & { w.enter(); return w; }, py::return_value_policy::reference)
      .def("__exit__", [](StopWork &w, const py::args &) { w.exit(); });
}

}  // namespace maze_mapper_python

PYBIND11_MODULE(_native, m) {
  namespace py = pybind11;
  m.doc() = "maze_mapper's grid, models, renderer, scorer and embedded simulator";
  static py::exception<common::InputError> error(m, "Error", PyExc_ValueError);
  static py::exception<common::NoSpaceError> no_space(m, "NoSpaceError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const common::InputError &e) {
      PyErr_SetString(error.ptr(), e.diagnostic().c_str());
    } catch (const common::NoSpaceError &e) {
      PyErr_SetString(no_space.ptr(), (std::string("error: ") + e.what()).c_str());
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
  maze_mapper_python::bind_signals(m);
}
