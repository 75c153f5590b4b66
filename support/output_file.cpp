#include "support/output_file.h"

namespace railjoint {

AtomicFile open_output_file(const std::filesystem::path& path, const char* option, int significant_digits) {
  return AtomicFile(path, option, significant_digits);
}

void write_output_file(const std::filesystem::path& path, const char* option,
                       const std::function<void(std::ostream&)>& write, int significant_digits) {
  AtomicFile out = open_output_file(path, option, significant_digits);
  write(out);
  out.commit();
}

}  // namespace railjoint
