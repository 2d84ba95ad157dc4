#include "validation_log.hpp"

#include <utility>

namespace penumbra::detail {

ValidationLog::ValidationLog(DiagnosticConsumer diagnostics)
    : diagnostics_(std::move(diagnostics)) {}

void ValidationLog::report(Severity severity, const std::string& message) {
  std::lock_guard lock(mutex_);
  diagnostics_({severity, "vulkan validation", message});
  if (severity != Severity::error) return;
  if (errors_++ == 0) first_error_ = message;
}

void ValidationLog::begin_call() {
  std::lock_guard lock(mutex_);
  errors_ = 0;
  first_error_.clear();
}

std::optional<Error> ValidationLog::end_call() {
  std::lock_guard lock(mutex_);
  if (errors_ == 0) return std::nullopt;
  return make_error(Error::Kind::device, "vulkan validation",
                    std::to_string(errors_) + " validation error(s), the first: " + first_error_);
}

}  // namespace penumbra::detail
