// Counts finished units for a ProgressConsumer, from any thread.
#pragma once

#include <chrono>
#include <mutex>

#include "penumbra/verify/progress.hpp"

namespace penumbra {

class ProgressCounter {
 public:
  // `consumer` may be empty: then nothing is told.
  ProgressCounter(ProgressConsumer consumer, std::size_t total)
      : consumer_(std::move(consumer)), total_(total) {}

  void finished(std::string unit) {
    if (!consumer_) return;
    const std::lock_guard lock(mutex_);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    consumer_({++done_, total_, seconds, std::move(unit)});
  }

 private:
  ProgressConsumer consumer_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace penumbra
