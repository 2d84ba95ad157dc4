#include "cpu_work.hpp"

#include <tbb/info.h>

#include <algorithm>

namespace penumbra {

// No more threads than TBB has: with fewer, a submit() blocked on a slot
// could wait for a worker that does not exist.
CpuWork::CpuWork(int jobs)
    : jobs_(jobs < 1 ? tbb::info::default_concurrency()
                     : std::min(jobs, tbb::info::default_concurrency())),
      arena_(jobs_),
      slots_(std::ptrdiff_t{2} * jobs_) {}

CpuWork::~CpuWork() {
  wait();
}

void CpuWork::run(const std::function<void()>& body) {
  arena_.execute(body);
}

void CpuWork::submit(std::function<void()> job) {
  // With one job, no worker would ever take a queued job while the caller
  // blocks on a slot: it runs here.
  if (jobs_ == 1) {
    job();
    return;
  }
  slots_.acquire();
  arena_.execute([&] {
    group_.run([this, job = std::move(job)] {
      job();
      slots_.release();
    });
  });
}

void CpuWork::wait() {
  arena_.execute([&] { group_.wait(); });
}

}  // namespace penumbra
