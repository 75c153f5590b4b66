#include "renders/video_assembly.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <sstream>
#include <vector>

namespace railjoint {

std::optional<std::filesystem::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    if (directory.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(directory) / program;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

VideoPipe::VideoPipe(const std::filesystem::path& out_dir, int width_px, int height_px, double video_fps)
    : out_dir_(out_dir), log_(out_dir / "ffmpeg.log") {
  const auto ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg) {
    failure_ = "ffmpeg not found on PATH: no crossing.mp4 / crossing.gif, the PNG frames are kept";
    return;
  }
  ffmpeg_ = ffmpeg->string();
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
  std::ostringstream rate;
  rate.precision(10);
  rate << video_fps;
  const std::string size = std::to_string(width_px) + "x" + std::to_string(height_px);
  // One input, two outputs: H.264 needs even sides; the GIF gets a palette
  // made from all its frames (palettegen waits for the end of the stream).
  // The GIF keeps the frame's size up to 1280 px wide: at 640 px the labels'
  // 2x font (crossing_setup.cpp text_scale) fell to about 5 px, unreadable.
  const std::vector<std::string> arguments = {
      "-hide_banner", "-loglevel", "error", "-xerror", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size,
      "-framerate", rate.str(), "-i", "-", "-filter_complex",
      "[0:v]split[v][g];[v]scale=trunc(iw/2)*2:trunc(ih/2)*2[mp4];"
      "[g]scale='min(1280,iw)':-2:flags=lanczos,split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse[gif]",
      "-map", "[mp4]", "-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-pix_fmt", "yuv420p",
      (out_dir / "crossing.mp4").string(), "-map", "[gif]", (out_dir / "crossing.gif").string()};

  ffmpeg_process_.emplace(ffmpeg_, arguments, ChildStreams{.input_from_railjoint = true, .output_to_error = true,
                                                             .error_log = log_});
  if (!ffmpeg_process_->started()) failure_ = "could not start ffmpeg: " + ffmpeg_process_->start_error();
}

void VideoPipe::write(const RgbImage& frame) {
  if (!running() || write_failed_) return;
  ++frames_;
  const int error = ffmpeg_process_->write_input(frame.rgb.data(), frame.rgb.size());
  if (error != 0) {
    write_failed_ = true;
    failure_ = std::string("writing frames to ffmpeg failed: ") + std::strerror(error);
  }
}

VideoFiles VideoPipe::finish() {
  VideoFiles result;
  if (!running()) {
    result.video_note = failure_;
    return result;
  }
  const ChildOutcome outcome = ffmpeg_process_->wait();
  if (frames_ == 0) {
    result.video_note = "no frames to assemble";
    return result;
  }
  if (outcome.succeeded() && failure_.empty()) {
    result.mp4 = out_dir_ / "crossing.mp4";
    result.gif = out_dir_ / "crossing.gif";
    result.video_note = "videos made by " + ffmpeg_ + " from " + std::to_string(frames_) + " raw frames piped to it";
    return result;
  }
  // ffmpeg's own status first: a closed pipe is the consequence of its exit.
  const std::string why = outcome.exit_status > 0   ? outcome.how
                          : outcome.exit_status < 0 ? "ffmpeg was " + outcome.how
                                                    : failure_;
  throw std::runtime_error("ffmpeg failed making crossing.mp4 / crossing.gif (" + why +
                           (outcome.last_error.empty() ? std::string() : ": " + outcome.last_error) + ")");
}

}  // namespace railjoint
