#pragma once
/// @file bounded.hpp
/// Reading a Python iterable of bounded size: a sized one (a list, a tuple, a numpy array)
/// over the cap is refused before its first item is read, an iterator without len() (a
/// generator, itertools.count()) as soon as it passes the cap, so no array, count or value
/// list from Python is allocated or iterated beyond its documented size.

#include <cstddef>
#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>

namespace covopt::python {

/// Calls `read(item)` for each item of `iterable`, at most `at_most` of them.
/// @throws std::invalid_argument "<what>: 100001 values is not allowed (at most 100000)", or
///         "<what>: more than 100000 values is not allowed (at most 100000)" for an iterator.
template <class Read>
void ForEachBounded(const pybind11::handle& iterable, std::size_t at_most, const std::string& what, Read&& read) {
  const auto refuse = [&](const std::string& count) {
    throw std::invalid_argument(what + ": " + count + " values is not allowed (at most " + std::to_string(at_most) +
                                ")");
  };
  if (pybind11::hasattr(iterable, "__len__")) {
    const Py_ssize_t size = PyObject_Length(iterable.ptr());
    if (size < 0) {
      PyErr_Clear();  // a __len__ that fails: count while iterating
    } else if (static_cast<std::size_t>(size) > at_most) {
      refuse(std::to_string(size));
    }
  }
  std::size_t count = 0;
  for (const pybind11::handle item : iterable) {
    if (++count > at_most) refuse("more than " + std::to_string(at_most));
    read(item);
  }
}

}  // namespace covopt::python
