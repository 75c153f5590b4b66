#include "renders/frame_finisher.h"

#include <algorithm>
#include <chrono>

#include "renders/png_file.h"

namespace railjoint {

namespace {
double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

FrameFinisher::FrameFinisher(int worker_count, int max_pending, std::function<void(const RgbImage&)> in_order)
    : in_order_(std::move(in_order)),
      max_pending_(static_cast<std::size_t>(std::max(1, max_pending))),
      max_spares_(max_pending_ + static_cast<std::size_t>(std::max(1, worker_count))) {
  for (int i = 0; i < std::max(1, worker_count); ++i) workers_.emplace_back([this] { work(); });
}

FrameFinisher::~FrameFinisher() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (auto& worker : workers_) worker.join();
}

void FrameFinisher::push(std::filesystem::path path, ReadBackFrame frame) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return jobs_.size() < max_pending_ || error_; });
  if (error_) std::rethrow_exception(error_);
  jobs_.push_back({pushed_++, std::move(path), std::move(frame)});
  lock.unlock();
  changed_.notify_all();
}

void FrameFinisher::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return (jobs_.empty() && busy_ == 0) || error_; });
  if (error_) std::rethrow_exception(error_);
}

ReadBackFrame FrameFinisher::spare_frame() {
  std::lock_guard lock(mutex_);
  if (spares_.empty()) return {};
  ReadBackFrame frame = std::move(spares_.back());
  spares_.pop_back();
  return frame;
}

long long FrameFinisher::written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

double FrameFinisher::total_finish_ms() const {
  std::lock_guard lock(mutex_);
  return total_finish_ms_;
}

double FrameFinisher::total_encode_ms() const {
  std::lock_guard lock(mutex_);
  return total_encode_ms_;
}

bool FrameFinisher::hand_over_in_order(long long sequence, const RgbImage& image) {
  std::unique_lock lock(mutex_);
  // Frames are taken from the queue in order, so the one this waits for is
  // already on another worker; a failure anywhere ends the wait.
  changed_.wait(lock, [&] { return next_in_order_ == sequence || error_; });
  if (error_) return false;
  lock.unlock();  // no other frame's turn comes before this one counts up
  in_order_(image);
  lock.lock();
  ++next_in_order_;
  lock.unlock();
  changed_.notify_all();
  return true;
}

void FrameFinisher::work() {
  RgbImage image;  // reused: its buffer is the size of every frame
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return !jobs_.empty() || stopping_; });
      if (jobs_.empty()) return;  // stopping and nothing left
      job = std::move(jobs_.front());
      jobs_.pop_front();
      ++busy_;
    }
    changed_.notify_all();  // room in the queue
    double finish_ms = 0.0, encode_ms = 0.0;
    bool handed_over = true;
    std::exception_ptr failure;
    try {
      const auto start = std::chrono::steady_clock::now();
      finish_frame(job.frame, image);
      finish_ms = ms_since(start);
      {
        std::lock_guard lock(mutex_);
        // No more spares than frames in flight; the rest are freed.
        if (spares_.size() < max_spares_) spares_.push_back(std::move(job.frame));
      }
      if (in_order_) handed_over = hand_over_in_order(job.sequence, image);
      const auto encode_start = std::chrono::steady_clock::now();
      if (handed_over) write_png(job.path, image);
      encode_ms = ms_since(encode_start);
    } catch (...) {
      failure = std::current_exception();
    }
    {
      std::lock_guard lock(mutex_);
      --busy_;
      if (failure) {
        if (!error_) error_ = failure;
        jobs_.clear();  // stop writing the rest after the first failure
      } else if (handed_over) {
        ++written_;
        total_finish_ms_ += finish_ms;
        total_encode_ms_ += encode_ms;
      }
    }
    changed_.notify_all();
  }
}

}  // namespace railjoint
