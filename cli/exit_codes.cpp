#include "exit_codes.hpp"

#include <iostream>
#include <mutex>
#include <regex>

#include "penumbra/support/text.hpp"

namespace penumbra::cli {

int report(const Error& error) {
  // A JSON path can hold a 10 MB key; the place and the message stay readable.
  // (std::regex also recurses per character: a long `where` would overflow the stack.)
  const std::string where = shorten(error.where, 200);
  // A place in a file ("x.json:3:14", "x.json:3:14: /sets/0/kernel" or,
  // without a column, "query.frag:12: variant ...") leads the line, as in a
  // compiler's messages, so editors can jump to it.
  static const std::regex kPlace(R"(^(.+:[0-9]+(:[0-9]+)?)(: (.*))?$)");
  std::smatch match;
  if (std::regex_match(where, match, kPlace)) {
    std::cerr << match[1] << ": error: " << (match[4].length() ? match[4].str() + ": " : "")
              << error.message << "\n";
  } else {
    std::cerr << "penumbra: error: " << (where.empty() ? "" : where + ": ") << error.message
              << "\n";
  }
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
