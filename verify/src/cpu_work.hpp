// CPU work handed off by the threads that drive the devices: the reference
// and the checks (verify), the pictures' figures and files (report). Each
// device thread drives its engines one call at a time; what they return is
// checked on the other cores meanwhile (oneTBB), so the devices and the CPU
// overlap.
#pragma once

#include <tbb/concurrent_queue.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <functional>
#include <mutex>

namespace penumbra {

class CpuWork {
 public:
  // At most `jobs` threads (0: every core) beside `device_threads` - 1 of
  // the device threads, each of which run()s a device loop: with 1, each job
  // runs at once in submit(), on the caller's thread.
  explicit CpuWork(int jobs, int device_threads = 1);
  ~CpuWork();  // waits for every job
  CpuWork(const CpuWork&) = delete;
  CpuWork& operator=(const CpuWork&) = delete;

  // Runs `body` (the device loop) with this work's thread limit applying to
  // every parallel loop it starts, the reference's included.
  void run(const std::function<void()>& body);
  // Queues `job`, which must not throw. While 2 x jobs wait, the caller
  // runs waiting jobs itself instead of going ahead: what waits for the CPU
  // does not pile up in memory, and no core idles while the CPU lags.
  void submit(std::function<void()> job);
  // Helps with, and waits for, every job submitted; from one thread, once
  // every device loop has ended.
  void wait();

  // The threads `jobs` means: 0, or more than TBB has workers for, is every
  // core.
  static int threads_for(int jobs);

 private:
  // Runs the oldest waiting job, if any: whoever takes it, a worker or the
  // caller.
  void run_one();

  int jobs_;
  tbb::task_arena arena_;
  tbb::task_group group_;
  std::mutex submitting_;  // group_'s tasks added from one device thread at a time
  tbb::concurrent_queue<std::function<void()>> waiting_;
};

}  // namespace penumbra
