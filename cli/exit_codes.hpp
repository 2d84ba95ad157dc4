// Exit codes (docs: README "The penumbra command") and error reporting for the commands.
#pragma once

#include "penumbra/support/diagnostics.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;  // a verification check failed
inline constexpr int kExitBadInput = 2;     // bad input or usage, with a message

// Prints "penumbra: error: <where>: <message>" to stderr, or, when `where`
// starts with FILE:LINE:COL, "FILE:LINE:COL: error: <rest of where>:
// <message>"; returns kExitBadInput.
int report(const Error& error);

// Diagnostics to stderr, notes only when `verbose`.
DiagnosticConsumer stderr_diagnostics(bool verbose);

}  // namespace penumbra::cli
