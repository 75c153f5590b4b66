#include "support/case_pool.h"

#include <chrono>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

#include <sched.h>

namespace railjoint {

int available_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

ChunkDispenser::ChunkDispenser(std::size_t count, std::size_t workers, std::size_t max_chunk)
    : count_(count), workers_(std::max<std::size_t>(workers, 1)), max_chunk_(std::max<std::size_t>(max_chunk, 1)) {}

Chunk ChunkDispenser::next() {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::size_t left = count_ - next_;
  // A quarter of each worker's share of what is left: big chunks while much
  // is left, single items at the end, so no worker idles long at the tail.
  std::size_t size = std::min({left, max_chunk_, std::max<std::size_t>(1, left / (4 * workers_))});
  const double per_item_s = timed_items_ > 0.0 ? timed_seconds_ / timed_items_ : 0.0;
  if (timed_items_ == 0.0) {
    size = std::min<std::size_t>(size, 1);
  } else if (per_item_s > 0.0) {
    size = std::min(size, static_cast<std::size_t>(std::max(1.0, kChunkSeconds / per_item_s)));
  }
  const Chunk chunk{next_, next_ + size};
  next_ += size;
  return chunk;
}

void ChunkDispenser::finished(Chunk chunk, double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  timed_items_ += static_cast<double>(chunk.end - chunk.begin);
  timed_seconds_ += seconds;
}

void run_chunks(ChunkDispenser& dispenser, int jobs, const std::function<void(Chunk)>& work) {
  std::mutex error_mutex;
  std::exception_ptr error;
  bool stop = false;
  const auto worker = [&] {
    for (;;) {
      {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (stop) return;
      }
      const Chunk chunk = dispenser.next();
      if (chunk.empty()) return;
      try {
        const auto start = std::chrono::steady_clock::now();
        work(chunk);
        dispenser.finished(chunk, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        stop = true;
        return;
      }
    }
  };
  std::vector<std::thread> threads;
  try {
    for (int i = 1; i < jobs; ++i) threads.emplace_back(worker);
  } catch (const std::system_error& refused) {
    // The system refused a thread (a thread limit, a memory limit on the
    // stacks): a std::thread still joinable at its destruction would abort.
    {
      std::lock_guard<std::mutex> lock(error_mutex);
      stop = true;
    }
    for (std::thread& thread : threads) thread.join();
    throw std::runtime_error("--jobs " + std::to_string(jobs) + ": the system refused to start thread " +
                             std::to_string(threads.size() + 2) + " (" + refused.what() +
                             "); give a smaller --jobs (this process may use " + std::to_string(available_cores()) +
                             " cores)");
  }
  worker();
  for (std::thread& thread : threads) thread.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace railjoint
