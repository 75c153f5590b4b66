#pragma once
// A path the Python module is given (a scene file, a sweep's out folder), as
// the file system takes it: a str, bytes or os.PathLike, by os.fspath and
// os.fsencode, so bytes are the file name's own bytes (never "b'...'") and a
// str Python decoded from a non-UTF-8 name (surrogateescape) names that file
// again. The C++ side opens paths by their bytes.

#include <string>

#include <pybind11/pybind11.h>

namespace railjoint::python {

/// The path's bytes. Raises TypeError naming `argument` for a value that is
/// no path, ValueError naming it for a path with a NUL (the C library would
/// cut the name there and open another file).
std::string path_argument(const pybind11::handle& value, const char* argument);

/// A path's bytes as Python shows file names (os.fsdecode): what
/// Scene.file and the messages hold.
pybind11::str path_text(const std::string& path);

}  // namespace railjoint::python
