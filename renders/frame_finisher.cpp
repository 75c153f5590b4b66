#include "renders/frame_finisher.h"

#include <chrono>
#include <utility>

#include "renders/png_file.h"

namespace railjoint {

namespace {
double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

FrameFinisher::FrameFinisher(std::function<void(const RgbImage&)> in_order) : in_order_(std::move(in_order)) {}

ReadBackFrame FrameFinisher::spare_frame() { return std::move(spare_); }

void FrameFinisher::push(const std::filesystem::path& path, ReadBackFrame frame) {
  const auto start = std::chrono::steady_clock::now();
  finish_frame(frame, image_);
  const double finish_ms = ms_since(start);
  spare_ = std::move(frame);
  if (in_order_) in_order_(image_);
  const auto encode_start = std::chrono::steady_clock::now();
  write_png(path, image_);
  total_encode_ms_ += ms_since(encode_start);
  total_finish_ms_ += finish_ms;
  ++written_;
}

}  // namespace railjoint
