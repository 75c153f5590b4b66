#include "scenes/profile_files.h"

#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include <nettle/sha2.h>

#include "models/profile_curve.h"
#include "scenes/input_file.h"
#include "support/input_error.h"

namespace railjoint {

namespace fs = std::filesystem;

namespace {

// Nettle (Debian's nettle-dev) rather than a hash of our own: a sweep
// fingerprint that must notice any change of a measured file.
std::string sha256_hex(const std::string& bytes) {
  sha256_ctx context;
  sha256_init(&context);
  sha256_update(&context, bytes.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()));
  std::uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&context, SHA256_DIGEST_SIZE, digest);
  std::string hex;
  char pair[3];
  for (const std::uint8_t byte : digest) {
    std::snprintf(pair, sizeof pair, "%02x", byte);
    hex += pair;
  }
  return hex;
}

}  // namespace

bool names_profile_file(std::string_view section, std::string_view key, std::string_view value) {
  if (section == "wheel" && key == "profile") return !value.empty();
  if (section == "joint" && key == "rail_profile") return value.size() > 4 && value.ends_with(".csv");
  return false;
}

ProfileKind profile_kind_of(std::string_view section) {
  return section == "wheel" ? ProfileKind::wheel_tread : ProfileKind::rail_head;
}

std::string profile_path_in(const fs::path& folder, const std::string& name) {
  const fs::path path(name);
  return (path.is_absolute() ? path : folder / path).lexically_normal().string();
}

fs::path folder_of(const std::string& file) {
  const fs::path parent = fs::path(file).parent_path();
  std::error_code ignored;
  return parent.is_absolute() ? parent : fs::current_path(ignored) / parent;
}

void anchor_profile_paths(toml::table& root, const fs::path& folder) {
  for (auto& [section_name, section] : root) {
    toml::table* table = section.as_table();
    if (table == nullptr) continue;
    for (auto& [key, value] : *table) {
      toml::value<std::string>* text = value.as_string();
      if (text == nullptr || !names_profile_file(section_name.str(), key.str(), text->get())) continue;
      *text = profile_path_in(folder, text->get());
    }
  }
}

const ProfileFiles::Bytes& ProfileFiles::read(const std::string& path) {
  if (const auto found = bytes_.find(path); found != bytes_.end()) return found->second;
  Bytes bytes;
  try {
    bytes.text = read_input_file(path, "profile");
    bytes.sha256 = sha256_hex(bytes.text);
  } catch (const InputError& error) {
    bytes.error = error.what();
  }
  return bytes_.emplace(path, std::move(bytes)).first->second;
}

const ProfileFile& ProfileFiles::get(const std::string& path, ProfileKind kind, double tolerance_m) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto key = std::make_tuple(path, kind, tolerance_m);
  if (const auto found = curves_.find(key); found != curves_.end()) return *found->second;
  const Bytes& bytes = read(path);
  auto file = std::make_unique<ProfileFile>();
  file->path = path;
  file->sha256 = bytes.sha256;
  file->error = bytes.error;
  if (bytes.error.empty()) {
    try {
      file->curve = std::make_shared<const ProfileCurve>(read_profile_csv(bytes.text, path, kind, tolerance_m));
    } catch (const std::invalid_argument& error) {
      file->error = path + ": " + error.what();
    }
  }
  return *curves_.emplace(key, std::move(file)).first->second;
}

}  // namespace railjoint
