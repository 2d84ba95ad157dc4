// Shader Model 3 guarantees 65,535 executed instructions a pixel. The
// hlsl_dx9 walks of minmax_pcf and backprojection (both traversals) take at
// most traits().walk_step_limit steps, and by vkd3d-compiler's own
// disassembly of the bytecode we ship, their longest path stays within it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <set>
#include <string>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_traits.hpp"
#include "sm3_executed.hpp"
#include "stages/stages.hpp"
#include "targets/sm3_slots.hpp"
#include "vkd3d/run_vkd3d.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

TEST(Sm3MostExecuted, TakesTheLongerArmAndRunsEachLoopItsTrips) {
  constexpr std::string_view kAssembly =
      "ps_3_0\n"
      "def c0 = 1.0, 0.0, 0.0, 0.0\n"
      "defi i0 = 255, 0, 0, 0\n"
      "mov r0, c0\n"             // 1
      "rep i0.xyzw\n"            // 1, then per trip: body + endrep
      "    if_ne r0.x, -r0.x\n"  //   1 + longer arm + endif
      "        break\n"          //     1
      "    else\n"               //     else arm: 1 + 3
      "        add r0, r0, c0\n"
      "        nrm r1.xyz, r0\n"  //     3 slots: 1 + 3 = 4 with add
      "    endif\n"
      "endrep\n"
      "mov oC0, r0\n";  // 1
  // Body: if 1 + max(1, 1 + 4) + endif 1 = 7; per trip 8; 3 trips 24.
  const auto executed = sm3_most_executed(kAssembly, {3});
  ASSERT_TRUE(executed.ok()) << executed.error().to_string();
  EXPECT_EQ(*executed, 1 + 1 + 3 * 8 + 1);
}

TEST(Sm3MostExecuted, LoopsAndTripCountsMustAgree) {
  constexpr std::string_view kAssembly = "ps_3_0\nrep i0\nmov r0, c0\nendrep\n";
  EXPECT_THAT(sm3_most_executed(kAssembly, {}).error().to_string(),
              HasSubstr("more loops than trip counts"));
  EXPECT_THAT(sm3_most_executed(kAssembly, {1, 2}).error().to_string(),
              HasSubstr("1 loops, 2 trip counts given"));
}

// The loops of a walk's query shader in the order vkd3d writes them: the
// mip walk's search for its start level (MINMAX_MAX_LEVEL), then the loop
// over `steps`: MINMAX_FOR_ONE_LOOP where the capped bound fits one loop,
// else the three nested loops of MINMAX_FOR_BOUNDED.
std::vector<long long> walk_trips(const Variant& variant, int steps) {
  std::vector<long long> trips;
  if (variant.keys.traversal != kBruteForceTraversal) trips.push_back(16);
  if (*walk_step_bound(variant, traits(Target::hlsl_dx9).walk_step_limit) <= 255) {
    trips.push_back(steps);
    return trips;
  }
  trips.push_back((steps + 65024) / 65025);
  trips.push_back(std::min((steps + 254) / 255, 255));
  trips.push_back(std::min(steps, 255));
  return trips;
}

// Every walk of the default library and of the largest manifest.
std::vector<Variant> walk_variants() {
  std::vector<Variant> variants = default_variants();
  auto largest =
      load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" / "largest.json");
  EXPECT_TRUE(largest.ok()) << largest.error().to_string();
  if (largest.ok()) variants.insert(variants.end(), largest->begin(), largest->end());
  // bitmask_backprojection has no hlsl_dx9 form (no integer bit operations),
  // nor has minmax_pcf above the kernels hlsl_dx9 counts exactly; both
  // manifests build minmax_pcf_k8.
  std::set<std::string> names;
  std::erase_if(variants, [&](const Variant& v) {
    return !walk_step_bound(v).has_value() || !can_emit(v, Target::hlsl_dx9) ||
           !names.insert(v.name).second;
  });
  for (Variant& variant : variants) variant.targets = {Target::hlsl_dx9};
  return variants;
}

TEST(Dx9WalkBound, EveryWalkStaysWithinPs30ExecutedInstructions) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  const std::vector<Variant> variants = walk_variants();
  // minmax_pcf k8 and k14 brute force, backprojection with both traversals.
  ASSERT_GE(variants.size(), 5u);
  const std::filesystem::path out = std::filesystem::path(::testing::TempDir()) /
                                    ("penumbra-walk-bound-" + std::to_string(::getpid()));
  const auto built = build_library(variants, out, {.jobs = 2, .hlsl = {.compiler = *compiler}},
                                   [](const Diagnostic&) {});
  ASSERT_TRUE(built.ok()) << built.error().to_string();
  const Result<Library> library = load_library(out);
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  const int limit = traits(Target::hlsl_dx9).walk_step_limit;
  for (const LibraryVariant& entry : library->variants) {
    SCOPED_TRACE(entry.variant.name);
    const int steps = walk_step_bound(entry.variant, limit).value();
    EXPECT_LE(steps, limit);
    const auto& bytecode = entry.passes.at(PassKind::query).at(Target::hlsl_dx9).frag_bytecode;
    ASSERT_TRUE(bytecode.has_value());
    const auto disassembly = run_vkd3d(
        *compiler, {"-x", "d3dbc", "-b", "d3d-asm", (library->root / bytecode->path).string()},
        std::chrono::seconds(30));
    ASSERT_TRUE(disassembly.ok() && disassembly->exit_code == 0);
    const auto executed = sm3_most_executed(disassembly->output, walk_trips(entry.variant, steps));
    ASSERT_TRUE(executed.ok()) << executed.error().to_string();
    EXPECT_LE(*executed, kPs30MinimumExecuted) << bytecode->path;
    // Without the cap the same code could run far past it.
    const auto uncapped = sm3_most_executed(
        disassembly->output, walk_trips(entry.variant, *walk_step_bound(entry.variant)));
    ASSERT_TRUE(uncapped.ok());
    if (*walk_step_bound(entry.variant) > 2 * limit) {
      EXPECT_GT(*uncapped, kPs30MinimumExecuted);
    }
  }
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace penumbra::testing
