#pragma once
// PNG encoding on worker threads, so the next frame renders while the last
// ones are encoded (encoding, not drawing, limits the frame rate: DESIGN.md).
// At most `max_pending` images wait in the queue; push() blocks beyond that,
// which bounds memory for long renders.

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "renders/rgb_image.h"

namespace railjoint {

class PngWriteQueue {
 public:
  PngWriteQueue(int worker_count, int max_pending);
  ~PngWriteQueue();  ///< waits for the workers; errors not yet collected by finish() are dropped
  PngWriteQueue(const PngWriteQueue&) = delete;
  PngWriteQueue& operator=(const PngWriteQueue&) = delete;

  /// Queues one file; rethrows the first error a worker has met so far.
  void push(std::filesystem::path path, RgbImage image);
  /// Waits until every queued file is written; rethrows the first error.
  void finish();

  long long written() const;
  double total_encode_ms() const;  ///< summed over files (per-file encode + write time on its worker)

 private:
  struct Job {
    std::filesystem::path path;
    RgbImage image;
  };
  void work();

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  std::size_t max_pending_;
  int busy_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  long long written_ = 0;
  double total_encode_ms_ = 0.0;
  std::vector<std::thread> workers_;
};

}  // namespace railjoint
