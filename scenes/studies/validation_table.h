#pragma once
// The table of `railjoint validate`: one row per validation scene (scenario,
// the three analytic forms, the simulated jump, the error against each, wall
// time, pass), printed as it runs and written as CSV and Markdown.

#include <ostream>
#include <string>
#include <vector>

#include "scenes/studies/validation_study.h"

namespace railjoint {

/// The column header of validation_line() with two spaces as separator.
extern const char* const kValidationHeader;

/// One row, fixed width, columns joined by `separator`.
std::string validation_line(const ValidationRow& row, const char* separator);

void write_validation_csv(const std::vector<ValidationRow>& rows, std::ostream& out);
void write_validation_markdown(const std::vector<ValidationRow>& rows, std::ostream& out);

}  // namespace railjoint
