#pragma once
// A study's table, each column declared once: its CSV name, its printed
// header with the unit, and how the text shows a value. The CSV file and the
// printed text (a Markdown table or fixed-width lines) are both written from
// the same rows, so a header cannot drift from the cells under it.

#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace railjoint {

/// A number that was not measured: NaN in the studies' results, an empty CSV cell.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Marks a column whose CSV texts are always in double quotes (free text: reasons, overrides).
struct StudyQuoted {};
inline constexpr StudyQuoted kQuoted{};

struct StudyColumn {
  std::string csv;  ///< CSV header, its unit in the name ("p1_N"); "" = only in the text
  /// Printed header, its unit in brackets ("P1 [kN]"); "" = only in the CSV; blanks = an empty header.
  std::string text;
  /// printf pattern of the printed cell: of value * scale for a number ("%.1f"), of a text
  /// when it holds %s ("%-22s"). "" = a text as it is (left-aligned in Markdown) or %g.
  std::string format;
  double scale = 1.0;  ///< printed number = value * scale (N -> kN: 1e-3)
  bool quoted = false;

  StudyColumn(std::string csv_name, std::string header = "", std::string pattern = "", double text_scale = 1.0)
      : csv(std::move(csv_name)), text(std::move(header)), format(std::move(pattern)), scale(text_scale) {}
  StudyColumn(std::string csv_name, std::string header, StudyQuoted)
      : csv(std::move(csv_name)), text(std::move(header)), quoted(true) {}
};

/// One cell: absent, a number, an integer, a yes/no or a text; `shown`, when
/// set, is what the text prints instead (a composite such as "2 landing").
struct StudyCell {
  std::variant<std::monostate, double, long long, bool, std::string> value;
  std::optional<std::string> shown;

  StudyCell() = default;
  StudyCell(double v) : value(v) {}
  StudyCell(int v) : value(static_cast<long long>(v)) {}
  StudyCell(std::size_t v) : value(static_cast<long long>(v)) {}
  StudyCell(bool v) : value(v) {}
  StudyCell(std::string v) : value(std::move(v)) {}
  StudyCell(const char* v) : value(std::string(v)) {}
  StudyCell(StudyCell csv, std::string text) : value(std::move(csv.value)), shown(std::move(text)) {}
};

/// Where a row goes: a printed table may show a selection of the CSV's rows.
enum class StudyRowIn { both, csv, text };

struct StudyTableStyle {
  std::string missing = "-";      ///< printed for an absent cell
  bool blank_non_finite = false;  ///< non-finite numbers as absent cells, else as printf writes them ("nan")
  bool plain_rule = false;        ///< Markdown rule "---" under every column
};

class StudyTable {
 public:
  explicit StudyTable(std::vector<StudyColumn> columns, StudyTableStyle style = {});
  /// A table for a CSV file only, its columns named by the header line ("t_s,x_m").
  static StudyTable csv_only(const std::string& header);

  /// Throws std::invalid_argument when the row has not one cell per column.
  void add(std::vector<StudyCell> cells, StudyRowIn in = StudyRowIn::both);

  /// The header line and the rows: numbers with 10 significant digits (no
  /// "-0"), booleans 1/0, an absent cell empty.
  void write_csv(std::ostream& out) const;
  /// "| header | ... |", the rule ("---:" under a column with a pattern), a line per row.
  std::string markdown() const;
  /// Fixed-width lines: cells joined by `separator` under a header padded to
  /// each pattern's width and leading text, up to its last non-empty header.
  std::string aligned(const std::string& separator, bool header = true) const;

  std::string csv_header() const;
  std::string csv_line(std::size_t row) const;
  std::string text_header() const;  ///< the Markdown header line, without '\n'
  std::string text_cell(std::size_t row, std::size_t column) const;

 private:
  struct Row {
    std::vector<StudyCell> cells;
    StudyRowIn in;
  };
  bool absent(const StudyCell& cell) const;
  std::vector<std::string> text_cells(std::size_t row) const;  ///< the headers for row = rows_.size()
  std::vector<StudyColumn> columns_;
  StudyTableStyle style_;
  std::vector<Row> rows_;
};

}  // namespace railjoint
