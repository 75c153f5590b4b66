#pragma once
// A long C++ run called from Python with the GIL released, stopped by Ctrl-C
// within a fraction of a second: on Python's main thread (the only one that
// runs signal handlers) the run polls a check (support/run_interrupt.h) that, at
// most every kSignalCheckPeriod, takes the GIL and runs the handlers. A
// KeyboardInterrupt (or any exception a handler raises) ends the run and is
// raised from the call, naming it. Other threads run without the check.

#include <chrono>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "support/run_interrupt.h"

namespace railjoint::python {

inline constexpr auto kSignalCheckPeriod = std::chrono::milliseconds(100);

/// f() with the GIL released, ended by Ctrl-C as above; `call` names the
/// call in the KeyboardInterrupt ("railjoint.simulate").
template <class F>
auto interruptible(const char* call, F f) {
  struct Interrupted {};  // the Python error waits in the indicator
  const pybind11::module_ threading = pybind11::module_::import("threading");
  const bool main_thread = threading.attr("current_thread")().is(threading.attr("main_thread")());
  std::optional<RunInterruptCheck> check;
  if (main_thread) {
    check.emplace([last = std::chrono::steady_clock::now()]() mutable {
      const auto now = std::chrono::steady_clock::now();
      if (now - last < kSignalCheckPeriod) return;
      last = now;
      pybind11::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) throw Interrupted{};
    });
  }
  try {
    pybind11::gil_scoped_release release;
    return f();
  } catch (const Interrupted&) {
    if (PyErr_ExceptionMatches(PyExc_KeyboardInterrupt)) {
      PyErr_Clear();
      PyErr_SetString(PyExc_KeyboardInterrupt, (std::string(call) + " interrupted: the run was stopped").c_str());
    }
    throw pybind11::error_already_set();
  }
}

}  // namespace railjoint::python
