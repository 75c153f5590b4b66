#include "support/render_folder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "support/interrupted_run.h"

namespace railjoint {

namespace fs = std::filesystem;

namespace {

// The renderer (renders/video_assembly.cpp) names ffmpeg's log so.
constexpr const char* kRendererLog = "ffmpeg.log";
constexpr const char* kPublishedLog = "crossing_ffmpeg.log";

bool is_frame_name(const std::string& name) {
  const std::string prefix = "frame_", suffix = ".png";
  if (name.size() < prefix.size() + 5 + suffix.size() || name.rfind(prefix, 0) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return false;
  }
  return std::all_of(name.begin() + static_cast<long>(prefix.size()), name.end() - static_cast<long>(suffix.size()),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

bool is_render_output(const std::string& name) {
  return is_frame_name(name) || name == "crossing.mp4" || name == "crossing.gif" || name == "crossing.glb" ||
         name == kPublishedLog;
}

std::string publish_render(StagingFolder& staging, const std::string& note) {
  // Ctrl-C now would leave part of the older render and part of the new one.
  const PublishingOutputs publishing;
  std::error_code ec;
  std::vector<std::pair<std::string, std::string>> moves;  // staged name, published name
  for (const std::string& name : staging.files()) {
    if (name != kRendererLog) {
      moves.emplace_back(name, name);
    } else if (fs::file_size(staging.path() / name, ec) > 0) {
      moves.emplace_back(name, kPublishedLog);
    }
  }
  // Before the older render goes: a name the new one cannot take would stop
  // the publication half way, the older render gone and the new one in part.
  for (const auto& [staged, published] : moves) staging.check_publishable(published);
  for (const fs::directory_entry& entry : fs::directory_iterator(staging.folder(), ec)) {
    if (entry.is_regular_file(ec) && is_render_output(entry.path().filename().string())) fs::remove(entry.path(), ec);
  }
  for (const auto& [staged, published] : moves) staging.publish(staged, published);
  std::string published = staging.published_text(note);
  const std::string log_path = (staging.folder() / kRendererLog).string();
  if (const std::size_t at = published.find(log_path); at != std::string::npos) {
    published.replace(at, log_path.size(), (staging.folder() / kPublishedLog).string());
  }
  return published;
}

}  // namespace railjoint
