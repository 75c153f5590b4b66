#pragma once
// The text `railjoint COMMAND --help` prints, for the docstring of the Python
// function that runs the same command (generated at build time from the
// executable by cli_help.cmake).

#include <string>

namespace railjoint::python {

/// "" for a command without a Python function.
std::string cli_help(const std::string& command);

}  // namespace railjoint::python

namespace railjoint::python {

/// A Python function's docstring: its own part (arguments, what it
/// returns), then the help of the command it runs, indented.
inline std::string command_doc(const std::string& python_part, const std::string& command) {
  std::string doc = python_part + "\nIt runs what `railjoint " + command + "` runs; the CLI's help:\n\n    ";
  for (const char c : cli_help(command)) {
    doc += c;
    if (c == '\n') doc += "    ";
  }
  return doc;
}

}  // namespace railjoint::python
