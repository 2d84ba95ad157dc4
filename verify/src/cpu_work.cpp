#include "cpu_work.hpp"

#include <tbb/info.h>

#include <algorithm>

namespace penumbra {

// No more threads than TBB has workers for: more would only queue.
int CpuWork::threads_for(int jobs) {
  return jobs < 1 ? tbb::info::default_concurrency()
                  : std::min(jobs, tbb::info::default_concurrency());
}

// Each device thread gets an arena slot of its own, so that none waits for
// another's to run its loop; the workers are as many as with one.
CpuWork::CpuWork(int jobs, int device_threads)
    : jobs_(threads_for(jobs)),
      arena_(jobs_ + device_threads - 1, static_cast<unsigned>(device_threads)) {}

CpuWork::~CpuWork() {
  wait();
}

void CpuWork::run(const std::function<void()>& body) {
  arena_.execute(body);
}

void CpuWork::run_one() {
  std::function<void()> job;
  if (waiting_.try_pop(job)) job();
}

void CpuWork::submit(std::function<void()> job) {
  if (jobs_ == 1) {
    job();
    return;
  }
  // One task per job, each running whichever job is oldest: a job the
  // caller ran itself leaves its task nothing to do.
  waiting_.push(std::move(job));
  arena_.execute([&] {
    const std::lock_guard lock(submitting_);
    group_.run([this] { run_one(); });
  });
  while (waiting_.unsafe_size() > std::size_t(2 * jobs_)) run_one();
}

void CpuWork::wait() {
  arena_.execute([&] { group_.wait(); });
}

}  // namespace penumbra
