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
#include <tuple>
#include <vector>

#include <toml++/toml.h>

namespace railjoint {

class ProfileCurve;
enum class ProfileKind;

/// Whether scene key `section.key` holding the text `value` names a profile
/// file: joint.rail_profile ending in .csv, wheel.profile when not empty.
bool names_profile_file(std::string_view section, std::string_view key, std::string_view value);

/// What the profile file named by `section.key` describes: a rail head for
/// joint.rail_profile, a wheel tread for wheel.profile.
ProfileKind profile_kind_of(std::string_view section);

/// `name` read from `folder` (an absolute name as given), lexically normal.
std::string profile_path_in(const std::filesystem::path& folder, const std::string& name);

/// The folder a relative name in `file` (a scene or sweep file as named, or
/// a stand-in such as "scene") is read from: the file's own, made absolute
/// against the current folder now.
std::filesystem::path folder_of(const std::string& file);

/// Every profile file named in the scene tree `root` made absolute against
/// `folder` (the scene file's): a scene's paths are relative to the scene.
void anchor_profile_paths(toml::table& root, const std::filesystem::path& folder);

/// One profile file, read once, as one kind of profile with one smoothing.
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
  /// The file at the absolute `path` as a profile of `kind` smoothed to
  /// `tolerance_m` (profile_curve.h): its bytes read the first time the
  /// path is asked for, the same bytes every later time, whatever kind or
  /// tolerance a later scene asks of them.
  const ProfileFile& get(const std::string& path, ProfileKind kind, double tolerance_m);

 private:
  struct Bytes {
    std::string text;    ///< the file's content
    std::string sha256;  ///< of text, in hex; empty when the file could not be read
    std::string error;   ///< why it could not be read, naming the file
  };
  const Bytes& read(const std::string& path);  ///< with mutex_ held

  mutable std::mutex mutex_;
  std::map<std::string, Bytes> bytes_;
  /// By path, kind and tolerance; unique_ptr: references stay valid.
  std::map<std::tuple<std::string, ProfileKind, double>, std::unique_ptr<const ProfileFile>> curves_;
};

}  // namespace railjoint
