#include "build/streamed_index.hpp"

#include <algorithm>
#include <chrono>

namespace penumbra {

StreamedIndex::StreamedIndex(std::span<const Variant> variants, std::vector<ShaderJob>& jobs)
    : variants_(variants),
      jobs_(jobs),
      table_(jobs),
      owner_(jobs.size()),
      first_job_(variants.size(), jobs.size()),
      left_(variants.size() + 1, 0) {
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Variant* variant = jobs[i].variant;
    owner_[i] = variant ? static_cast<std::size_t>(variant - variants.data()) : variants.size();
    if (variant) first_job_[owner_[i]] = std::min(first_job_[owner_[i]], i);
    ++left_[owner_[i]];
  }
}

void StreamedIndex::take(ShaderJob& job) {
  if (job.bytecode) ++bytecode_;
  if (job.from_cache) ++cached_;
  inputs_.insert(job.inputs.begin(), job.inputs.end());
  std::vector<std::string>().swap(job.inputs);
}

void StreamedIndex::finished(std::size_t i) {
  const std::scoped_lock lock(mutex_);
  --left_[owner_[i]];
  // Every record needs the shared shaders: nothing before they are done.
  if (left_[variants_.size()] != 0) return;
  const auto start = std::chrono::steady_clock::now();
  while (written_ < variants_.size() && left_[written_] == 0) {
    const Variant& variant = variants_[written_];
    index_.add(resolve_variant(variant, table_));
    for (std::size_t j = first_job_[written_]; j < jobs_.size() && owner_[j] == written_; ++j) {
      take(jobs_[j]);
      jobs_[j].reflection = {};
    }
    ++written_;
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string StreamedIndex::finish() {
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < jobs_.size(); ++i) {
    if (owner_[i] == variants_.size()) take(jobs_[i]);
  }
  std::string text = index_.finish();
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return text;
}

}  // namespace penumbra
