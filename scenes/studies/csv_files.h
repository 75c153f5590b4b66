#pragma once
// Where a study that writes several CSV files puts them: the caller (a
// command) decides the folder and what a file that cannot be written means;
// the study only names its files.

#include <functional>
#include <string>

#include "support/atomic_file.h"

namespace railjoint {

/// Opens a CSV file of that name for writing (10 significant digits), or
/// throws; the study commits each file when it has written all of it.
using CsvFiles = std::function<AtomicFile(const std::string& name)>;

}  // namespace railjoint
