#pragma once
// Outputs of several files (a mesh with its .mtl or .bin, a render's frames
// and videos) written whole or not at all: they are written into a fresh
// hidden folder inside the target folder (the same file system, so moving a
// file out of it is an atomic rename) and published one by one once all of
// them are complete. A run that fails on the way leaves the target folder as
// it found it; the staging folder goes with the StagingFolder object.

#include <filesystem>
#include <string>
#include <vector>

#include "support/interrupted_run.h"

namespace railjoint {

class StagingFolder {
 public:
  /// Creates `folder`/.railjoint-staging-<pid>-XXXXXX (`folder` must exist),
  /// after removing those of runs that no longer exist (temporary_name.h).
  /// Throws InputError naming `named` (default: the folder) and `option`
  /// when it cannot.
  StagingFolder(const std::filesystem::path& folder, std::string option, const std::filesystem::path& named = {});
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;
  /// Removes the staging folder with whatever was not published.
  ~StagingFolder();

  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& folder() const { return folder_; }

  /// The names of the files written into the staging folder, sorted.
  std::vector<std::string> files() const;

  /// Moves the staged file `name` to folder()/`final_name`: a rename that
  /// replaces an older file of that name in one step (a symbolic link to a
  /// file stays a link; the file it points to is replaced), or a checked
  /// copy when that name is a device or a FIFO (AtomicFile's rules). Throws
  /// std::runtime_error naming the file when it cannot.
  void publish(const std::string& name, const std::string& final_name);
  /// Publishes every staged file under its own name, after checking that
  /// each name can take it (check_publishable). The caller holds a
  /// PublishingOutputs (interrupted_run.h) across the folders it publishes.
  void publish_all();
  /// Throws InputError naming folder()/`final_name` when no file can be
  /// published there (a folder has that name): called for every name before
  /// the first publish(), so a render never stops half published.
  void check_publishable(const std::string& final_name) const;

  /// `text` with the staging folder's path replaced by the target folder's:
  /// a message that names a staged file names the published one.
  std::string published_text(std::string text) const;

 private:
  std::filesystem::path folder_;
  std::filesystem::path path_;
  std::string option_;
  RemovedIfInterrupted removed_if_interrupted_;  ///< the staging folder (interrupted_run.h)
};

}  // namespace railjoint
