// index.json written while a build runs: each variant's record goes to the
// IndexWriter as soon as its shaders and the shared ones are done, in
// library order, and its jobs then drop their reflections, so that memory
// does not grow with the variant count.
#pragma once

#include <mutex>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "build/index_json.hpp"

namespace penumbra {

class StreamedIndex {
 public:
  // `jobs` as plan_jobs() orders them: the shared ones first, then each
  // variant's own together, in the order of `variants`.
  StreamedIndex(std::span<const Variant> variants, std::vector<ShaderJob>& jobs);

  // Job `i` succeeded. Safe to call from several threads.
  void finished(std::size_t i);

  // After every job succeeded: index.json's text.
  std::string finish();

  std::size_t bytecode() const { return bytecode_; }  // bytecode files
  std::size_t cached() const { return cached_; }      // jobs restored from the cache
  std::size_t written() const { return written_; }    // variant records written
  // Seconds spent writing records and index.json's text, under the lock.
  double seconds() const { return seconds_; }
  // The shaderlib files the jobs read (paths relative to the shaderlib).
  const std::set<std::string>& inputs() const { return inputs_; }

 private:
  // Counts a finished job and frees what its variant's record held.
  void take(ShaderJob& job);

  std::span<const Variant> variants_;
  std::vector<ShaderJob>& jobs_;
  JobTable table_;
  IndexWriter index_;
  std::vector<std::size_t> owner_;      // per job: its variant, or variants_.size() when shared
  std::vector<std::size_t> first_job_;  // per variant: where its jobs start
  std::vector<std::size_t> left_;       // per variant, then the shared: jobs not yet finished
  std::size_t written_ = 0;             // variants given to the index so far
  std::size_t bytecode_ = 0;
  std::size_t cached_ = 0;
  double seconds_ = 0.0;
  std::set<std::string> inputs_;
  std::mutex mutex_;
};

}  // namespace penumbra
