#pragma once
// Where a study that writes several CSV files puts them: the caller (a
// command) decides the folder and what a file that cannot be written means;
// the study only names its files.

#include <fstream>
#include <functional>
#include <string>

namespace railjoint {

/// Opens a CSV file of that name for writing (10 significant digits), or throws.
using CsvFiles = std::function<std::ofstream(const std::string& name)>;

}  // namespace railjoint
