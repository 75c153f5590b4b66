#pragma once
// The output folder a command writes into: shared by every command that
// writes files (each file through support/output_file.h).

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "support/output_file.h"  // open_output_file, write_output_file: every command writes its files through them

namespace railjoint::cli {

/// Creates `dir` and makes sure files can be written there, before any
/// simulation runs: a typo should not cost a run. Throws InputError naming
/// the folder and `option`, the command-line option that named it.
void prepare_output_folder(const std::filesystem::path& dir, const char* option);

/// Refuses a file output at the same path as another output of the same
/// command (a file or a folder): one would overwrite, or be replaced by, the
/// other, or the folder made first would leave the file nothing to write.
/// Paths are compared made absolute, with what exists of them resolved
/// (`a/../t.csv`, `./t.csv` and a symbolic link to it are all `t.csv`).
/// Throws InputError naming the file and both options.
void refuse_same_output(const std::filesystem::path& file, const char* file_option,
                        const std::filesystem::path& other, const char* other_option);

}  // namespace railjoint::cli
