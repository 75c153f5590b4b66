#include "renders/png_write_queue.h"

#include <algorithm>
#include <chrono>

#include "renders/png_file.h"

namespace railjoint {

PngWriteQueue::PngWriteQueue(int worker_count, int max_pending)
    : max_pending_(static_cast<std::size_t>(std::max(1, max_pending))) {
  for (int i = 0; i < std::max(1, worker_count); ++i) workers_.emplace_back([this] { work(); });
}

PngWriteQueue::~PngWriteQueue() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (auto& worker : workers_) worker.join();
}

void PngWriteQueue::push(std::filesystem::path path, RgbImage image) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return jobs_.size() < max_pending_ || error_; });
  if (error_) std::rethrow_exception(error_);
  jobs_.push_back({std::move(path), std::move(image)});
  lock.unlock();
  changed_.notify_all();
}

void PngWriteQueue::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return (jobs_.empty() && busy_ == 0) || error_; });
  if (error_) std::rethrow_exception(error_);
}

long long PngWriteQueue::written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

double PngWriteQueue::total_encode_ms() const {
  std::lock_guard lock(mutex_);
  return total_encode_ms_;
}

void PngWriteQueue::work() {
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
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr failure;
    try {
      write_png(job.path, job.image);
    } catch (...) {
      failure = std::current_exception();
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    {
      std::lock_guard lock(mutex_);
      --busy_;
      if (failure) {
        if (!error_) error_ = failure;
        jobs_.clear();  // stop writing the rest after the first failure
      } else {
        ++written_;
        total_encode_ms_ += ms;
      }
    }
    changed_.notify_all();
  }
}

}  // namespace railjoint
