#pragma once
// Turning the PNG frames into crossing.mp4 and crossing.gif with ffmpeg when
// it is on PATH. ffmpeg runs without a shell (arguments passed as a list, so
// folder names with spaces or quotes are safe); its messages go to
// <frame folder>/ffmpeg.log.

#include <filesystem>
#include <optional>
#include <string>

namespace railjoint {

/// The first executable named `program` in the directories of $PATH.
std::optional<std::filesystem::path> find_on_path(const std::string& program);

struct VideoResult {
  std::optional<std::filesystem::path> mp4;
  std::optional<std::filesystem::path> gif;
  std::string note;  ///< what happened, for the report (e.g. "ffmpeg not found on PATH; frames kept")
};

/// Assembles frame_00000.png .. frame_<count-1>.png in `frame_dir` into
/// crossing.mp4 (H.264, yuv420p) and crossing.gif (at most 640 px wide),
/// played back at `video_fps`. Never throws for a missing or failing ffmpeg:
/// the frames are the product, the videos a convenience; the note says why
/// a video is missing.
VideoResult assemble_videos(const std::filesystem::path& frame_dir, long long frame_count, double video_fps);

}  // namespace railjoint
