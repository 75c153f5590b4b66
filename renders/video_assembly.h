#pragma once
// crossing.mp4 and crossing.gif made by ffmpeg while the frames are drawn:
// each frame goes to ffmpeg's standard input as raw RGB (no PNG decoded
// again), written after each frame is drawn and finished; drawing waits for the pipe when ffmpeg falls behind. One ffmpeg process writes both
// files (H.264 yuv420p, and a GIF at most 1280 px wide with its own palette).
// ffmpeg runs as railjoint's other children do (support/child_process.h:
// no shell, so folder names with spaces or quotes are safe; killed when
// railjoint is interrupted); its messages go to <folder>/ffmpeg.log through
// a pipe that keeps their last lines in memory too: on a full disk the log
// cannot be written, and its last line is what says why.
// ffmpeg runs with -xerror: without it a write error (a full disk) is logged
// and ffmpeg still exits 0 having left a truncated video.

#include <filesystem>
#include <optional>
#include <string>

#include "renders/rgb_image.h"
#include "renders/video_files.h"
#include "support/child_process.h"

namespace railjoint {

/// The first executable named `program` in the directories of $PATH.
std::optional<std::filesystem::path> find_on_path(const std::string& program);

class VideoPipe {
 public:
  /// Starts ffmpeg for frames of width x height at `video_fps` frames per
  /// wall-clock second into out_dir/crossing.mp4 and crossing.gif. Never
  /// throws for a missing ffmpeg (the frames are the product, the videos a
  /// convenience; finish() says why there is none), but finish() throws when
  /// ffmpeg ran and failed: its videos are not whole. Destroyed unfinished,
  /// it closes the pipe and waits for ffmpeg (its failure then unreported).
  VideoPipe(const std::filesystem::path& out_dir, int width_px, int height_px, double video_fps);

  bool running() const { return ffmpeg_process_ && ffmpeg_process_->started(); }
  /// Writes one frame (same size as given to the constructor) to ffmpeg's
  /// input, blocking until the pipe has taken it; one caller at a time, in
  /// frame order. Ignored when ffmpeg is not running
  /// or a write failed already (finish() says so).
  void write(const RgbImage& frame);
  /// Closes ffmpeg's input, waits for it and reports what it made; call it once. Throws
  /// std::runtime_error when ffmpeg failed (exit status, signal, a closed
  /// pipe), with its exit status and the last line it logged (e.g. "Error
  /// writing trailer of .../crossing.gif: File too large").
  VideoFiles finish();

 private:
  std::filesystem::path out_dir_;
  std::filesystem::path log_;
  std::string ffmpeg_;
  std::optional<ChildProcess> ffmpeg_process_;
  long long frames_ = 0;
  std::string failure_;  ///< why ffmpeg could not be started or fed
  bool write_failed_ = false;
};

}  // namespace railjoint
