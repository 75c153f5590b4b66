#pragma once
// Frame finishing, the CPU's share of every frame, as one unit on one pool of
// worker threads while the calling thread draws the next frame. Per frame:
// (ReadBackFrame) => RGB rows, FXAA and labels (finish_frame,
// renders/read_back_frame.h, fxaa.h, label_raster.h) => the sink, in frame
// order (the video: VideoPipe::write, renders/video_assembly.h, which writes
// to ffmpeg on the worker whose turn it is) => the PNG file (png_file.h).
// Drawing is the one serial step; everything after it runs two frames at a
// time. At most `max_pending` frames wait in the queue; push() blocks beyond
// that, which bounds memory for long renders.

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "renders/read_back_frame.h"
#include "renders/rgb_image.h"

namespace railjoint {

class FrameFinisher {
 public:
  /// `in_order`, if given, receives every finished frame in the order the
  /// frames were pushed, one at a time (a worker that finished early waits
  /// for its turn); it must not throw.
  FrameFinisher(int worker_count, int max_pending, std::function<void(const RgbImage&)> in_order = {});
  ~FrameFinisher();  ///< waits for the workers; errors not yet collected by finish() are dropped
  FrameFinisher(const FrameFinisher&) = delete;
  FrameFinisher& operator=(const FrameFinisher&) = delete;

  /// Queues one frame for `path`; rethrows the first error a worker has met so far.
  void push(std::filesystem::path path, ReadBackFrame frame);
  /// A frame the workers are done with, its buffers kept (empty at first):
  /// drawing into it spares the allocation and first touch of two
  /// frame-sized buffers a frame.
  ReadBackFrame spare_frame();
  /// Waits until every queued frame is written; rethrows the first error.
  void finish();

  long long written() const;
  double total_finish_ms() const;  ///< summed over frames: finish_frame (RGB rows, FXAA, labels) on the workers
  double total_encode_ms() const;  ///< summed over frames: PNG encode + file write on the workers

 private:
  struct Job {
    long long sequence = 0;
    std::filesystem::path path;
    ReadBackFrame frame;
  };
  void work();
  /// Waits for frame `sequence`'s turn and hands `image` to in_order_; false when a failure ended the run.
  bool hand_over_in_order(long long sequence, const RgbImage& image);

  std::function<void(const RgbImage&)> in_order_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  std::vector<ReadBackFrame> spares_;
  std::size_t max_pending_;
  std::size_t max_spares_;  ///< frames in flight at most: queued + one per worker
  long long pushed_ = 0;
  long long next_in_order_ = 0;  ///< the frame in_order_ waits for
  int busy_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  long long written_ = 0;
  double total_finish_ms_ = 0.0;
  double total_encode_ms_ = 0.0;
  std::vector<std::thread> workers_;
};

}  // namespace railjoint
