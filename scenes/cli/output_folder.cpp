#include "scenes/cli/output_folder.h"

#include <fstream>
#include <system_error>

#include "support/input_error.h"

namespace railjoint::cli {

void prepare_output_folder(const std::filesystem::path& dir, const char* option) {
  // (An error with no file is given the scene file's name by the command.)
  if (dir.empty()) throw InputError("\"\"", option, "an empty path: give the folder to write into");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir.string(), option,
                     "cannot create this folder: " + (ec ? ec.message() : std::string("a file of that name exists")));
  }
  const std::filesystem::path probe = dir / ".railjoint_write_probe";
  {
    std::ofstream file(probe, std::ios::binary | std::ios::trunc);
    if (!file) throw InputError(dir.string(), option, "this folder is not writable");
  }
  std::filesystem::remove(probe, ec);
}

void refuse_same_output(const std::filesystem::path& file, const char* file_option,
                        const std::filesystem::path& other, const char* other_option) {
  std::error_code ec_file, ec_other;
  const std::filesystem::path a = std::filesystem::weakly_canonical(std::filesystem::absolute(file), ec_file);
  const std::filesystem::path b = std::filesystem::weakly_canonical(std::filesystem::absolute(other), ec_other);
  // A path that cannot be resolved is left to the writer, which names its own error.
  if (ec_file || ec_other || a != b) return;
  throw InputError(file.string(), file_option,
                   std::string("is also the path given to ") + other_option + ": give each output a path of its own");
}

}  // namespace railjoint::cli
