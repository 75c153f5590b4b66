#pragma once
// An output file by the one atomic path (atomic_file.h), for every writer
// that writes a whole file: the commands' files, the sweep's manifest, the
// pressure figures' data.

#include <filesystem>
#include <functional>
#include <ostream>

#include "support/atomic_file.h"

namespace railjoint {

/// A file to write numbers into (10 significant digits unless asked
/// otherwise), written whole or not at all: it gets its name when the
/// caller commits it. Throws InputError naming the file and `option` (the
/// command-line option that named it) if it cannot be created.
AtomicFile open_output_file(const std::filesystem::path& path, const char* option, int significant_digits = 10);

/// One output file written whole: open_output_file, `write` fills it, then
/// commit. An exception from `write` leaves no file (an older one of that
/// name stays as it was).
void write_output_file(const std::filesystem::path& path, const char* option,
                       const std::function<void(std::ostream&)>& write, int significant_digits = 10);

}  // namespace railjoint
