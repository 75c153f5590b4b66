#pragma once
// The table of `railjoint validate`: one row per validation scene (scenario,
// the three analytic forms, the simulated jump, the error against each, wall
// time, pass), printed as it runs and written as CSV and Markdown.

#include <vector>

#include "scenes/studies/study_table.h"
#include "scenes/studies/validation_study.h"

namespace railjoint {

/// The printed header above validation_table(rows).aligned("  ", false).
extern const char* const kValidationHeader;

/// validation.csv, validation.md (markdown()) and the printed lines.
StudyTable validation_table(const std::vector<ValidationRow>& rows);

}  // namespace railjoint
