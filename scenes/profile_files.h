#pragma once
// Measured profile files (CSV) that scenes name: where a relative name is
// found, and each file read once by its absolute path and kept with its
// content's SHA-256. Every scene read from one source (a sweep's cases, a
// Python Scene's checks) uses the content read when the source was loaded,
// never a file opened again later from whatever folder is current then; a
// sweep's fingerprint holds the hashes, so a resume on a changed profile is
// refused.

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace railjoint {

class ProfileCurve;

/// Whether scene key `section.key` holding the text `value` names a profile
/// file: joint.rail_profile ending in .csv, wheel.profile when not empty.
bool names_profile_file(std::string_view section, std::string_view key, std::string_view value);

/// `name` read from `folder` (an absolute name as given), lexically normal.
std::string profile_path_in(const std::filesystem::path& folder, const std::string& name);

/// The folder a relative name in `file` (a scene or sweep file as named, or
/// a stand-in such as "scene") is read from: the file's own, made absolute
/// against the current folder now.
std::filesystem::path folder_of(const std::string& file);

/// Every profile file named in the scene tree `root` made absolute against
/// `folder` (the scene file's): a scene's paths are relative to the scene.
void anchor_profile_paths(toml::table& root, const std::filesystem::path& folder);

/// One profile file, read once.
struct ProfileFile {
  std::string path;    ///< absolute
  std::string sha256;  ///< of the bytes read, in hex; empty when the file could not be read
  std::shared_ptr<const ProfileCurve> curve;  ///< null when it could not be read or parsed
  std::string error;   ///< why not, naming the file, when curve is null
};

/// The profile files of one source, each read on first use and then kept.
/// Thread-safe: a sweep's workers share one.
class ProfileFiles {
 public:
  /// The file at the absolute `path`, read and parsed the first time it is
  /// asked for, the same content every later time.
  const ProfileFile& get(const std::string& path);
  /// Every file read so far, by path.
  std::vector<ProfileFile> files() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::unique_ptr<const ProfileFile>> files_;  ///< unique_ptr: references stay valid
};

}  // namespace railjoint
