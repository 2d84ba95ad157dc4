// screen_blur's chain as the tests that run it on an engine read it: each
// pass's image out of the targets an engine's run_passes returns.
#pragma once

#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::testing {

// What the chain's passes wrote, each the receivers' size.
struct ScreenChain {
  FloatImage factor;       // the query's .x
  FloatImage texel_reads;  // the query's .y
  FloatImage blurred_h;    // blur_h's .x
  FloatImage blurred;      // blur_v's .x: the blurred factor
  FloatImage composite;    // the composite's four channels
};

// The chain's images; an error names a pass that did not run.
Result<ScreenChain> screen_chain(const runtime::PassOutputs& outputs);

}  // namespace penumbra::testing
