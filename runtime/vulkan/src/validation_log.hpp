// ValidationLog: turns validation-layer messages into diagnostics and makes
// an engine call fail when the layer reported an error during it.
#pragma once

#include <cstddef>
#include <mutex>
#include <optional>
#include <string>

#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::detail {

class ValidationLog {
 public:
  explicit ValidationLog(DiagnosticConsumer diagnostics);

  // From the debug messenger: forwards the message and counts it if an error.
  void report(Severity severity, const std::string& message);

  // Brackets one engine call.
  void begin_call();
  // The first error reported since begin_call(), as an Error; none if none.
  std::optional<Error> end_call();

 private:
  std::mutex mutex_;  // layers may report from any thread that calls into Vulkan
  DiagnosticConsumer diagnostics_;
  std::size_t errors_ = 0;
  std::string first_error_;
};

// Runs `call` (returning a Result) between begin_call() and end_call(); a
// successful result becomes the validation Error if the layer reported one.
template <typename Call>
auto run_validated(ValidationLog& log, Call&& call) -> decltype(call()) {
  log.begin_call();
  auto result = call();
  std::optional<Error> error = log.end_call();
  if (error && result.ok()) return *error;
  return result;
}

}  // namespace penumbra::detail
