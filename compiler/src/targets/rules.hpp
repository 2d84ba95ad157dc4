// Target rules: constructs a target cannot express, checked on the SPIR-V
// before emitting so the message names variant, target and construct.
#pragma once

#include "penumbra/compiler/stage.hpp"

namespace penumbra {

Status check_target_rules(const ShaderJob& job);

}  // namespace penumbra
