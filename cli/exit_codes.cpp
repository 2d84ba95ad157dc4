#include "exit_codes.hpp"

#include <iostream>
#include <mutex>

namespace penumbra::cli {

int report(const Error& error) {
  std::cerr << "penumbra: error: " << error.to_string() << "\n";
  return kExitBadInput;
}

DiagnosticConsumer stderr_diagnostics(bool verbose) {
  return [verbose](const Diagnostic& d) {
    static std::mutex mutex;
    if (d.severity == Severity::note && !verbose) return;
    const char* label = d.severity == Severity::error     ? "error"
                        : d.severity == Severity::warning ? "warning"
                                                          : "note";
    std::lock_guard lock(mutex);
    std::cerr << "penumbra: " << label << ": " << (d.where.empty() ? "" : d.where + ": ")
              << d.message << "\n";
  };
}

}  // namespace penumbra::cli
