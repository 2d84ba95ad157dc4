// The suites run the Vulkan engine with the validation layers on and expect
// no message from them.
#pragma once

#include "penumbra/support/diagnostics.hpp"

namespace penumbra::testing {

// Fails the running test on every validation-layer message (warnings too)
// and when the layers are missing; drops other diagnostics.
DiagnosticConsumer fail_on_validation_messages();

}  // namespace penumbra::testing
