#include "support/staging_folder.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include "support/atomic_file.h"
#include "support/input_error.h"
#include "support/temporary_name.h"

namespace railjoint {

namespace fs = std::filesystem;

StagingFolder::StagingFolder(const fs::path& folder, std::string option, const fs::path& named)
    : folder_(folder.empty() ? fs::path(".") : folder), option_(std::move(option)) {
  remove_stale_staging_folders(folder_);  // left by runs killed outright
  std::string pattern = (folder_ / staging_folder_pattern(getpid())).string();
  if (mkdtemp(pattern.data()) == nullptr) {
    const bool a_file = !named.empty();
    throw InputError((a_file ? named : folder_).string(), option_,
                     std::string(a_file ? "cannot write this file (does its folder exist?): "
                                        : "cannot write into this folder: ") +
                         std::strerror(errno));
  }
  path_ = pattern;
  removed_if_interrupted_ = RemovedIfInterrupted(path_);
}

StagingFolder::~StagingFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

std::vector<std::string> StagingFolder::files() const {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(path_)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void StagingFolder::publish(const std::string& name, const std::string& final_name) {
  const fs::path staged = path_ / name;
  const fs::path target = folder_ / final_name;
  std::error_code ec;
  // Its bytes written to the target through an AtomicFile (a temporary
  // beside the file a link points to, or a checked write to a device).
  const auto copy_to_target = [&] {
    AtomicFile out(target, option_);
    std::ifstream in(staged, std::ios::binary);
    if (fs::file_size(staged, ec) > 0) out << in.rdbuf();  // (an empty rdbuf sets failbit)
    out.commit();
    fs::remove(staged, ec);
  };
  const fs::file_status status = fs::status(target, ec);  // follows links
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    copy_to_target();  // a device or a FIFO
    return;
  }
  fs::path destination = target;
  if (fs::is_symlink(fs::symlink_status(target, ec))) {
    const fs::path resolved = fs::canonical(target, ec);
    if (!ec) destination = resolved;  // a dangling link is replaced itself
  }
  ec.clear();
  fs::rename(staged, destination, ec);
  if (ec == std::errc::cross_device_link) {
    copy_to_target();  // a link to a file on another file system
    return;
  }
  if (ec) throw std::runtime_error(target.string() + " (" + option_ + "): cannot write this file: " + ec.message());
}

void StagingFolder::publish_all() {
  const std::vector<std::string> names = files();
  for (const std::string& name : names) check_publishable(name);
  for (const std::string& name : names) publish(name, name);
}

void StagingFolder::check_publishable(const std::string& final_name) const {
  refuse_a_folder_as_file(folder_ / final_name, option_);
}

std::string StagingFolder::published_text(std::string text) const {
  const std::string from = path_.string();
  const std::string to = folder_.string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace railjoint
