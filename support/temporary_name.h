#pragma once
// The hidden name an AtomicFile (and a figure script, scripts/plots/
// atomic_save.py) writes under before it renames the file into place:
// ".<name>.railjoint-<pid>-<n>", or ".railjoint-<pid>-<n>" when <name> is
// too long to repeat. A process killed outright (SIGKILL, a crash, the OOM
// killer) cannot remove its temporary, so the next write into that folder
// removes the temporaries of processes that no longer exist; the pid in the
// name says whose it was. The same for a staging folder.

#include <filesystem>
#include <optional>
#include <string>

#include <sys/types.h>

namespace railjoint {

/// The temporary for a file named `target_name`, written by process `pid`,
/// the `attempt`-th name tried.
std::string temporary_name(const std::string& target_name, pid_t pid, int attempt);

/// The pid in a name temporary_name() makes; nullopt for any other name.
std::optional<pid_t> temporary_owner(const std::string& name);

/// Removes the regular files in `folder` named by temporary_name() whose
/// process no longer exists (kill(pid, 0) fails with ESRCH). Nothing else
/// is touched, and errors are ignored: it is tidying, not the write.
void remove_stale_temporaries(const std::filesystem::path& folder);

/// The mkdtemp pattern of a staging folder (support/staging_folder.h)
/// made by process `pid`: ".railjoint-staging-<pid>-XXXXXX".
std::string staging_folder_pattern(pid_t pid);

/// The pid in a name staging_folder_pattern() makes (its X's filled in);
/// nullopt for any other name.
std::optional<pid_t> staging_folder_owner(const std::string& name);

/// Removes the folders in `folder` named by staging_folder_pattern() whose
/// process no longer exists (a render killed outright leaves its frames
/// there, hundreds of MB), with what they hold. Not a symbolic link, not
/// any other name; errors are ignored.
void remove_stale_staging_folders(const std::filesystem::path& folder);

}  // namespace railjoint
