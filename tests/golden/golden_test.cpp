// Golden files: the text emitted for one representative variant of each
// technique (its passes, and its function form where it has one), and for
// the shared passes, for every target, compared with the
// reference copies under tests/golden/reference/ so that any change in the
// emitted code shows up in review. PENUMBRA_UPDATE_GOLDEN=1 rewrites the
// references instead of comparing (docs/golden.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <spirv-tools/libspirv.hpp>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "build/pass_plan.hpp"
#include "default_library.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

const fs::path kReference = fs::path(PENUMBRA_SOURCE_DIR) / "tests" / "golden" / "reference";

constexpr const char* kHowToUpdate =
    "If the change is intended, rewrite the references with `ninja update-golden` (or "
    "PENUMBRA_UPDATE_GOLDEN=1 penumbra_golden_tests) and commit them with the change; see "
    "docs/golden.md.\n";

// One variant per technique, from the default manifest so that the goldens
// follow its disks, or from kExtraVariants.
constexpr const char* kRepresentatives[] = {"hard",
                                            "pcf_grid_k3",
                                            "pcf_poisson_p16_whitepaper16",
                                            "pcss_b16_p16_whitepaper16",
                                            "minmax_pcf_k6",
                                            "backprojection",
                                            "pcss_minmax_p16_whitepaper16",
                                            "screen_blur_r4",
                                            "bitmask_backprojection_bits64",
                                            "pcss_b16_p16_poisson_perspective_reversed",
                                            "pcss_b16_p16_poisson_orthographic"};

// Representatives the default manifest does not build: an even kernel that
// every target counts exactly (hlsl_dx9 up to K = 8), and the NVIDIA PCSS
// whitepaper's disk for pcss_minmax.
constexpr const char* kExtraVariants = R"({
  "schema": 1,
  "sets": [
    { "technique": "minmax_pcf", "kernel": 6 },
    { "technique": "backprojection" },
    { "technique": "pcss_minmax", "pcf_samples": 16, "disk": "whitepaper16" }
  ]
})";

bool update_mode() {
  const char* value = std::getenv("PENUMBRA_UPDATE_GOLDEN");
  return value && std::string(value) == "1";
}

const Variant& representative(const std::string& name) {
  static const std::vector<Variant> variants = [] {
    std::vector<Variant> out = penumbra::testing::default_variants();
    auto manifest = parse_manifest(kExtraVariants, "golden extra variants");
    auto extra = manifest.ok() ? expand(*manifest) : Result<std::vector<Variant>>(manifest.error());
    if (extra.ok()) out.insert(out.end(), extra->begin(), extra->end());
    return out;
  }();
  for (const Variant& v : variants) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("permutations/default.json has no variant " + name);
}

// "pcss/hlsl_dx9/query.frag.hlsl"; SPIR-V is kept as disassembly (.spvasm).
fs::path golden_path(const std::string& dir, Target target, std::string_view stem,
                     ShaderStage stage) {
  std::string name = output_file_name(target, stem, stage);
  if (target == Target::spirv) name += "asm";
  return fs::path(dir) / std::string(to_string(target)) / name;
}

std::string emitted_text(const CompiledStage& stage, Target target) {
  if (target != Target::spirv) return stage.text;
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  std::string text;
  // No header: it names the generator's version, which differs between machines.
  tools.Disassemble(stage.spirv, &text,
                    SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT |
                        SPV_BINARY_TO_TEXT_OPTION_NO_HEADER);
  return text;
}

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// `diff -u` of the reference against the emitted text.
std::string unified_diff(const fs::path& reference, const std::string& actual,
                         const std::string& label) {
  std::string flat = label;
  for (char& c : flat) c = c == '/' ? '_' : c;
  const fs::path emitted = fs::path(::testing::TempDir()) / ("penumbra-golden-" + flat);
  std::ofstream(emitted, std::ios::binary) << actual;
  const std::string command = "diff -u --label " + quoted("reference/" + label) + " --label " +
                              quoted("emitted/" + label) + " " + quoted(reference.string()) + " " +
                              quoted(emitted.string()) + " 2>&1";
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    pclose(pipe);
  }
  fs::remove(emitted);
  return out.empty() ? "(diff produced no output; compare the files by hand)\n" : out;
}

void expect_golden(const fs::path& relative, const std::string& actual) {
  const fs::path path = kReference / relative;
  EXPECT_EQ(actual.find(PENUMBRA_SOURCE_DIR), std::string::npos)
      << relative << " names the source directory, which differs between machines";
  if (update_mode()) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ADD_FAILURE() << "no reference file " << path << "\n" << kHowToUpdate;
    return;
  }
  std::stringstream expected;
  expected << in.rdbuf();
  if (expected.str() == actual) return;
  ADD_FAILURE() << relative.generic_string() << " differs from its reference:\n"
                << unified_diff(path, actual, relative.generic_string()) << kHowToUpdate;
}

std::string target_name(const ::testing::TestParamInfo<Target>& param_info) {
  return std::string(to_string(param_info.param));
}

// The fragment stages a variant owns: query, and screen_blur's blur_h and
// blur_v.
std::vector<const PassStageSource*> variant_sources(const Variant& variant) {
  std::vector<const PassStageSource*> out;
  for (const PassStageSource& source : pass_plan()) {
    if (source.per_variant && runs_pass(source.pass, variant)) out.push_back(&source);
  }
  return out;
}

// A representative's folder: its technique, and its map encoding unless linear.
std::string golden_dir(const Variant& variant) {
  const MapEncoding encoding = map_encoding(variant.keys);
  return std::string(to_string(variant.technique)) +
         (encoding == MapEncoding::linear ? "" : "_" + std::string(to_string(encoding)));
}

class VariantPasses : public ::testing::TestWithParam<std::tuple<const char*, Target>> {};

TEST_P(VariantPasses, MatchTheReference) {
  const auto [name, target] = GetParam();
  const Variant& variant = representative(name);
  if (std::ranges::find(variant.targets, target) == variant.targets.end()) {
    GTEST_SKIP() << name << " is not emitted for " << to_string(target);
  }
  const std::string dir = golden_dir(variant);
  for (const PassStageSource* source : variant_sources(variant)) {
    auto pass = compile_pass(variant, target, source->pass);
    ASSERT_TRUE(pass.ok()) << pass.error().to_string();
    expect_golden(golden_path(dir, target, source->file_stem, ShaderStage::fragment),
                  emitted_text(pass->frag, target));
  }
}

INSTANTIATE_TEST_SUITE_P(Golden, VariantPasses,
                         ::testing::Combine(::testing::ValuesIn(kRepresentatives),
                                            ::testing::ValuesIn(kAllTargets)),
                         [](const auto& param_info) {
                           const Variant& v = representative(std::get<0>(param_info.param));
                           return golden_dir(v) + "_" +
                                  std::string(to_string(std::get<1>(param_info.param)));
                         });

// The function form of each representative that has one, per text target:
// "pcss/glsl450/penumbra_visibility.glsl".
class VariantFunctions : public ::testing::TestWithParam<std::tuple<const char*, Target>> {};

fs::path function_golden_path(const std::string& dir, Target target) {
  return fs::path(dir) / std::string(to_string(target)) /
         (traits(target).is_hlsl ? "penumbra_visibility.hlsl" : "penumbra_visibility.glsl");
}

bool has_function_golden(const Variant& variant, Target target) {
  return has_function_form(variant.technique) && traits(target).is_text &&
         std::ranges::find(variant.targets, target) != variant.targets.end();
}

// The (representative, target) pairs that have a function form.
std::vector<std::tuple<const char*, Target>> function_pairs() {
  std::vector<std::tuple<const char*, Target>> out;
  for (const char* name : kRepresentatives) {
    for (Target target : kAllTargets) {
      if (has_function_golden(representative(name), target)) out.emplace_back(name, target);
    }
  }
  return out;
}

TEST_P(VariantFunctions, MatchTheReference) {
  const auto [name, target] = GetParam();
  const Variant& variant = representative(name);
  auto function = compile_function(variant, target);
  ASSERT_TRUE(function.ok()) << function.error().to_string();
  expect_golden(function_golden_path(golden_dir(variant), target), function->text);
}

INSTANTIATE_TEST_SUITE_P(Golden, VariantFunctions, ::testing::ValuesIn(function_pairs()),
                         [](const auto& param_info) {
                           const Variant& v = representative(std::get<0>(param_info.param));
                           return golden_dir(v) + "_" +
                                  std::string(to_string(std::get<1>(param_info.param)));
                         });

// The stages variants share, each compiled through a representative that
// runs its pass: every shared stage of the pass plan (depth, the full-screen
// vertex shaders, the min-max build passes, composite).
const char* shared_representative(PassKind pass) {
  if (pass == PassKind::deferred) return "hard";
  return pass == PassKind::blur_h || pass == PassKind::blur_v || pass == PassKind::composite
             ? "screen_blur_r4"
             : "backprojection";
}

std::vector<const PassStageSource*> shared_sources() {
  std::vector<const PassStageSource*> out;
  for (const PassStageSource& source : pass_plan()) {
    if (!source.per_variant) out.push_back(&source);
  }
  return out;
}

class SharedPasses : public ::testing::TestWithParam<Target> {};

TEST_P(SharedPasses, MatchTheReference) {
  const Target target = GetParam();
  for (const PassStageSource* source : shared_sources()) {
    const Variant& variant = representative(shared_representative(source->pass));
    auto pass = compile_pass(variant, target, source->pass);
    ASSERT_TRUE(pass.ok()) << pass.error().to_string();
    const CompiledStage& stage = source->stage == ShaderStage::vertex ? pass->vert : pass->frag;
    expect_golden(golden_path("common", target, source->file_stem, source->stage),
                  emitted_text(stage, target));
  }
}

INSTANTIATE_TEST_SUITE_P(Golden, SharedPasses, ::testing::ValuesIn(kAllTargets), target_name);

// A reference no test compares against any more (a renamed output, a
// dropped target) would silently rot: the tree holds exactly the goldens.
TEST(GoldenReference, HoldsOnlyCurrentGoldens) {
  std::set<fs::path> expected;
  for (Target target : kAllTargets) {
    for (const char* name : kRepresentatives) {
      const Variant& variant = representative(name);
      const std::string dir = golden_dir(variant);
      for (const PassStageSource* source : variant_sources(variant)) {
        expected.insert(golden_path(dir, target, source->file_stem, ShaderStage::fragment));
      }
      if (has_function_golden(variant, target)) {
        expected.insert(function_golden_path(dir, target));
      }
    }
    for (const PassStageSource* source : shared_sources()) {
      expected.insert(golden_path("common", target, source->file_stem, source->stage));
    }
  }
  if (update_mode()) fs::create_directories(kReference);  // this test may run first
  ASSERT_TRUE(fs::is_directory(kReference)) << "no reference tree " << kReference << "\n"
                                            << kHowToUpdate;
  for (const auto& entry : fs::recursive_directory_iterator(kReference)) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), kReference);
    if (expected.contains(relative)) continue;
    if (update_mode()) {
      fs::remove(entry.path());
    } else {
      ADD_FAILURE() << "stale reference file " << relative << "\n" << kHowToUpdate;
    }
  }
}

}  // namespace
}  // namespace penumbra
