#pragma once
// Frame finishing, the CPU's share of every frame, on the calling thread after
// it draws: (ReadBackFrame) => RGB rows, FXAA and labels (finish_frame,
// renders/read_back_frame.h, fxaa.h, label_raster.h) => the sink, in frame
// order (the video: VideoPipe::write, renders/video_assembly.h) => the PNG
// file (png_file.h). A pool of two workers did this beside the drawing until
// 2026-11-27; with ffmpeg setting the pace of a render it saved no time the
// user sees (docs/rendering.md, "Frame times").

#include <filesystem>
#include <functional>

#include "renders/read_back_frame.h"
#include "renders/rgb_image.h"

namespace railjoint {

class FrameFinisher {
 public:
  /// `in_order`, if given, receives every finished frame in the order the
  /// frames were pushed.
  explicit FrameFinisher(std::function<void(const RgbImage&)> in_order = {});

  /// Finishes one frame, hands it to the sink and writes it to `path`;
  /// throws what finishing or writing throws (the frame is then not written).
  void push(const std::filesystem::path& path, ReadBackFrame frame);
  /// The last frame pushed, its buffers kept (empty at first): drawing into
  /// it spares the allocation and first touch of two frame-sized buffers a frame.
  ReadBackFrame spare_frame();

  long long written() const { return written_; }
  double total_finish_ms() const { return total_finish_ms_; }  ///< summed over frames: RGB rows, FXAA, labels
  double total_encode_ms() const { return total_encode_ms_; }  ///< summed over frames: PNG encode + file write

 private:
  std::function<void(const RgbImage&)> in_order_;
  ReadBackFrame spare_;
  RgbImage image_;  // reused: its buffer is the size of every frame
  long long written_ = 0;
  double total_finish_ms_ = 0.0;
  double total_encode_ms_ = 0.0;
};

}  // namespace railjoint
