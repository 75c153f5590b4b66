#pragma once
// What ffmpeg made of a run's frames (video_assembly.h), as every report of
// drawn frames names it: the render, the patch crossing, the solved contact.

#include <filesystem>
#include <optional>
#include <string>

namespace railjoint {

struct VideoFiles {
  std::optional<std::filesystem::path> mp4;
  std::optional<std::filesystem::path> gif;
  /// What ffmpeg made, or why there is no video (e.g. "ffmpeg not found on PATH; frames kept").
  std::string video_note;
};

}  // namespace railjoint
