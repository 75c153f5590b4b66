#pragma once
// A CSV table as the CLI writes it (--csv) turned into columns: a dict from
// each header name to a read-only NumPy float64 array, an empty cell as NaN;
// a column with no value in any row (not applicable to this run: the
// thesis's linearised path of the general model) is None, as the JSON's null.
// The module has the CLI's writers write the CSV text (with every digit of a
// double) and reads it here, so the columns are the CLI's, in its order. The
// text is read line by line as it is written, never held whole (10 million
// rows of a time history are 1.9 GB of text), into the arrays' own buffers.

#include <cstddef>
#include <streambuf>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace railjoint::python {

/// Significant digits that write a double so it reads back unchanged.
inline constexpr int kExactDigits = 17;

/// The buffer of a stream the CLI's writers write into: each complete line
/// is read into the columns as the buffer fills. Called with the GIL held; it
/// runs Python's signal handlers every few thousand rows, so Ctrl-C stops a
/// long table (a handler's exception is thrown as error_already_set).
/// Throws std::runtime_error for a cell that is not a number or a row of
/// another width (a bug: the writers it reads write numbers only).
class CsvColumnsBuffer : public std::streambuf {
 public:
  /// `rows_hint`: the rows expected, reserved up front (0: unknown).
  explicit CsvColumnsBuffer(std::size_t rows_hint);
  /// The columns read; call once, after the writer has finished.
  pybind11::dict columns();

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  void read_lines();
  void read_line(std::string_view line);

  std::vector<char> buffer_;
  std::size_t rows_hint_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
  std::vector<bool> has_value_;  ///< a column with a cell that is not empty
  bool header_read_ = false;
  std::size_t rows_ = 0;
};

}  // namespace railjoint::python
