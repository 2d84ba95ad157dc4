#include "validation_messages.hpp"

#include <gtest/gtest.h>

namespace penumbra::testing {

DiagnosticConsumer fail_on_validation_messages() {
  return [](const Diagnostic& diagnostic) {
    // The engine names the layers as the place of their messages, and warns
    // as "vulkan" when they are missing: then nothing would be checked.
    if (diagnostic.where == "vulkan validation" ||
        (diagnostic.where == "vulkan" && diagnostic.severity != Severity::note)) {
      ADD_FAILURE() << diagnostic.where << ": " << diagnostic.message;
    }
  };
}

}  // namespace penumbra::testing
