#pragma once
// copy.copy, copy.deepcopy and pickle of a result (Prediction, Simulation,
// Pressure). Its C++ run (a Bullet trajectory, the model it ran) is not
// carried; its Python face is: every property's value, its as_dict() and its
// columns (trajectory, traversal). The copy is that face, read-only as the
// original: each property, as_dict() and the columns return the same values.
// A result holds `pybind11::object frozen` (None for one computed here).

#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include <pybind11/pybind11.h>

namespace railjoint::python {

/// {"fields": {property: value}, "as_dict": as_dict(), "columns": the
/// `columns_property` (or None)}: every public property of the class.
pybind11::dict frozen_state(const pybind11::object& self, const char* columns_property);

/// The frozen property, or None when it is missing from the state.
pybind11::object frozen_field(const pybind11::object& frozen, const char* name);

/// A copy of the frozen as_dict() (the caller may change its dict).
pybind11::object frozen_report(const pybind11::object& frozen);

/// The frozen columns.
pybind11::object frozen_columns(const pybind11::object& frozen);

/// A property's value as Python holds it (a pybind11 object as it is).
template <class V>
pybind11::object as_python(V&& value) {
  if constexpr (std::is_base_of_v<pybind11::handle, std::decay_t<V>>) {
    return pybind11::reinterpret_borrow<pybind11::object>(value);
  } else {
    return pybind11::cast(std::forward<V>(value));
  }
}

/// Adds the read-only property `name`: `get(result)` as Python holds it, or
/// for an unpickled result its frozen value. T must hold `pybind11::object frozen`.
template <class T, class... Options, class Get>
void add_result_property(pybind11::class_<T, Options...>& c, const char* name, Get get, const char* doc) {
  c.def_property_readonly(
      name,
      [get, name](const T& result) -> pybind11::object {
        return result.frozen ? frozen_field(result.frozen, name) : as_python(get(result));
      },
      doc);
}

/// A run's columns (trajectory, traversal): an unpickled run's frozen ones,
/// else made by `make()` on first use and kept in `kept`, so that a caller
/// who never looks pays nothing.
template <class Make>
pybind11::object columns_on_first_use(const pybind11::object& frozen, pybind11::object& kept, Make make) {
  if (frozen) return frozen_columns(frozen);
  if (!kept) kept = make();
  return kept;
}

/// Adds __getstate__ and __setstate__ to the class: T must hold
/// `pybind11::object frozen` and be default constructible.
template <class T, class... Options>
void add_frozen_pickle(pybind11::class_<T, Options...>& c, const char* columns_property) {
  c.def(pybind11::pickle(
      [columns_property](const pybind11::object& self) { return frozen_state(self, columns_property); },
      [](const pybind11::dict& state) {
        T result{};
        result.frozen = state;
        return result;
      }));
}

/// Adds __copy__ and __deepcopy__ to a run held by shared_ptr: the same C++
/// run (nothing in it changes), its columns cached in `columns` made again on use.
template <class T, class... Options>
void add_run_copy(pybind11::class_<T, Options...>& c, pybind11::object T::*columns) {
  const auto copy = [columns](const T& run) {
    auto twin = std::make_shared<T>(run);
    (*twin).*columns = pybind11::object();
    return twin;
  };
  c.def("__copy__", copy);
  c.def("__deepcopy__", [copy](const T& run, const pybind11::dict&) { return copy(run); });
}

}  // namespace railjoint::python
