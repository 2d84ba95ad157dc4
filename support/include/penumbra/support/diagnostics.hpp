// Diagnostics: library code reports progress and warnings to an injected
// consumer, never to stdout/stderr directly.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace penumbra {

enum class Severity { note, warning, error };

struct Diagnostic {
  Severity severity = Severity::note;
  std::string where;    // variant/target/file the message is about; may be empty
  std::string message;  // one line
};

// Receives diagnostics. Producers call it from the thread that called them
// unless they document otherwise.
using DiagnosticConsumer = std::function<void(const Diagnostic&)>;

// A consumer that drops everything (for tests and quiet callers).
inline DiagnosticConsumer ignore_diagnostics() {
  return [](const Diagnostic&) {};
}

}  // namespace penumbra
