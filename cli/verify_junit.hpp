// `penumbra verify --junit`: a verification's report as JUnit (docs/scale-out.md).
#pragma once

#include "junit.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra::cli {

// The report as one JUnit suite, named after the shard and carrying
// kJunitShardProperty: a testcase per check, classname the variant (or
// depth_pass, minmax_mip) and name TARGET/BACKEND/SCENE (TARGET/SCENE; a run
// that failed or did not execute before any scene: TARGET/BACKEND).
JunitReport to_junit(const VerifyReport& report);

}  // namespace penumbra::cli
