// The embedded shaders against the library they came from, embedded in
// parts (penumbra_add_shader_library) and whole (`penumbra embed` alone):
// every program of index.json is found, by name and by technique and keys,
// with the files' bytes, the SPIR-V words, the bytecode and the reflection.
#include "penumbra/compiler/embed.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <tuple>

#include "embed_function/shaders.hpp"
#include "embed_test/shaders.hpp"
#include "embed_whole/shaders.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

const Library& built() {
  static const Library library = [] {
    auto loaded = load_library(PENUMBRA_EMBEDDED_LIBRARY);
    EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
    return loaded.ok() ? std::move(*loaded) : Library{};
  }();
  return library;
}

std::string file_text(const std::string& relative) {
  auto text = read_file(built().root / relative);
  EXPECT_TRUE(text.ok()) << relative;
  return text.ok() ? *text : std::string();
}

void expect_stage(const shaders::StageCode& code, Target target, const std::string& path,
                  const std::optional<BytecodeFile>& bytecode) {
  if (target == Target::spirv) {
    auto words = read_spirv_file(built().root / path);
    ASSERT_TRUE(words.ok());
    EXPECT_TRUE(std::ranges::equal(code.spirv, *words)) << path;
    EXPECT_TRUE(code.text.empty());
  } else {
    EXPECT_EQ(code.text, file_text(path)) << path;
    EXPECT_TRUE(code.spirv.empty());
  }
  if (!bytecode) {
    EXPECT_TRUE(code.bytecode.empty()) << path;
    return;
  }
  const std::string bytes = file_text(bytecode->path);
  EXPECT_TRUE(std::ranges::equal(code.bytecode, bytes, {}, {}, [](char c) {
    return static_cast<std::uint8_t>(c);
  })) << bytecode->path;
  EXPECT_EQ(code.profile, bytecode->profile);
}

struct Embedding {
  const char* name;
  const shaders::Library& (*library)();
};

class Embedded : public ::testing::TestWithParam<Embedding> {
 protected:
  const shaders::Library& library() const { return GetParam().library(); }
};

TEST_P(Embedded, EveryProgramOfTheLibraryWithItsFilesAndReflection) {
  std::size_t programs = 0, with_bytecode = 0;
  for (const LibraryVariant& entry : built().variants) {
    for (const auto& [pass, by_target] : entry.passes) {
      for (const auto& [target, files] : by_target) {
        SCOPED_TRACE(entry.variant.name + " " + std::string(to_string(target)) + " " +
                     std::string(to_string(pass)));
        const shaders::Program* program = library().find(entry.variant.name, target, pass);
        ASSERT_NE(program, nullptr);
        EXPECT_EQ(program->variant, entry.variant.name);
        expect_stage(program->vertex, target, files.vert, files.vert_bytecode);
        expect_stage(program->fragment, target, files.frag, files.frag_bytecode);
        EXPECT_EQ(nlohmann::json::parse(program->reflection),
                  nlohmann::json(entry.reflection.at(pass).at(target)));
        ++programs;
        with_bytecode += files.frag_bytecode.has_value();
      }
    }
  }
  EXPECT_EQ(library().size(), programs);
  const std::vector<const shaders::Program*> all = library().programs();
  EXPECT_EQ(all.size(), programs);
  EXPECT_TRUE(std::ranges::is_sorted(all, {}, [](const shaders::Program* p) {
    return std::make_tuple(p->variant, static_cast<int>(p->target), static_cast<int>(p->pass));
  }));
  EXPECT_GT(programs, 80u);
  EXPECT_GT(with_bytecode, 20u);  // the Direct3D targets, built with vkd3d-compiler
}

TEST_P(Embedded, FoundByTechniqueAndKeys) {
  const shaders::Program* pcss = library().find(
      Technique::pcss, {.blocker_samples = 16, .pcf_samples = 16, .disk = "whitepaper16"},
      Target::hlsl_dx10);
  ASSERT_NE(pcss, nullptr);
  EXPECT_EQ(pcss->variant, "pcss_b16_p16_whitepaper16");
  EXPECT_EQ(pcss->fragment.profile, "ps_4_0");
  EXPECT_THAT(pcss->fragment.text, ::testing::HasSubstr("SampleCmpLevelZero"));
  const shaders::Program* depth =
      library().find(Technique::minmax_pcf, {.kernel = 8}, Target::spirv, PassKind::minmax_reduce);
  ASSERT_NE(depth, nullptr);
  ASSERT_FALSE(depth->fragment.spirv.empty());
  EXPECT_EQ(depth->fragment.spirv[0], 0x07230203u);  // SPIR-V's magic
  // Keys, targets and passes the library does not hold.
  EXPECT_EQ(library().find(Technique::pcss,
                           {.blocker_samples = 32, .pcf_samples = 16, .disk = "whitepaper16"},
                           Target::hlsl_dx10),
            nullptr);
  EXPECT_EQ(library().find(Technique::hard, {}, Target::hlsl_dx9, PassKind::blur_h), nullptr);
}

TEST_P(Embedded, EveryFunctionFormWithItsFileAndReflection) {
  std::size_t functions = 0;
  for (const LibraryVariant& entry : built().variants) {
    for (const auto& [target, form] : entry.function) {
      SCOPED_TRACE(entry.variant.name + " " + std::string(to_string(target)));
      const shaders::Function* function = library().find_function(entry.variant.name, target);
      ASSERT_NE(function, nullptr);
      EXPECT_EQ(function->variant, entry.variant.name);
      EXPECT_EQ(function->target, target);
      EXPECT_EQ(function->text, file_text(form.file));
      EXPECT_EQ(nlohmann::json::parse(function->reflection), nlohmann::json(form.reflection));
      ++functions;
    }
  }
  EXPECT_EQ(library().functions().size(), functions);
  EXPECT_EQ(functions, 18u);  // hard, pcss and minmax_pcf, on the six text targets
  const shaders::Function* pcss = library().find_function(
      Technique::pcss, {.blocker_samples = 16, .pcf_samples = 16, .disk = "whitepaper16"},
      Target::glsl330);
  ASSERT_NE(pcss, nullptr);
  EXPECT_THAT(pcss->text,
              ::testing::HasSubstr("float penumbra_visibility(vec4 light_clip_position)"));
  EXPECT_EQ(library().find_function("hard", Target::spirv), nullptr);  // no includable SPIR-V
  EXPECT_NE(library().find_function("minmax_pcf_k8", Target::glsl450), nullptr);
  EXPECT_EQ(library().find_function("screen_blur_r2", Target::glsl450), nullptr);
}

// The header's find() is the library's.
TEST(EmbeddedHeader, FindIsTheLibrarysFind) {
  const VariantKeys keys{.blocker_samples = 16, .pcf_samples = 16, .disk = "whitepaper16"};
  EXPECT_EQ(embed_test::find(Technique::pcss, keys, Target::spirv),
            embed_test::library().find(Technique::pcss, keys, Target::spirv));
  EXPECT_EQ(embed_whole::find(Technique::pcss, keys, Target::spirv),
            embed_whole::library().find(Technique::pcss, keys, Target::spirv));
  EXPECT_EQ(embed_test::find_function(Technique::pcss, keys, Target::essl300),
            embed_test::library().find_function(Technique::pcss, keys, Target::essl300));
}

TEST_P(Embedded, EachVariantsFormsAreIndexJsons) {
  for (const LibraryVariant& entry : built().variants) {
    EXPECT_EQ(library().forms(entry.variant.name), entry.variant.forms) << entry.variant.name;
  }
  EXPECT_EQ(library().why_no_function("screen_blur_r2", Target::glsl450),
            "variant screen_blur_r2 was built without the function form (its forms: query)");
}

// FORMS function (penumbra build --form function): the function forms, the
// depth pass and the min-max chain they read, no query or deferred pass,
// and no variant without a function form.
TEST(EmbeddedForms, AFunctionFormLibraryHoldsWhatItReadsAndSaysWhatItLacks) {
  const shaders::Library& library = embed_function::library();
  EXPECT_EQ(library.forms("pcss_b16_p16_whitepaper16"), std::vector<Form>{Form::function});
  EXPECT_EQ(library.functions().size(), 18u);  // hard, pcss and minmax_pcf, six text targets
  EXPECT_NE(library.find("minmax_pcf_k8", Target::glsl450, PassKind::depth), nullptr);
  EXPECT_NE(library.find("minmax_pcf_k8", Target::glsl450, PassKind::minmax_reduce), nullptr);
  for (const shaders::Program* program : library.programs()) {
    EXPECT_TRUE(program->pass == PassKind::depth || program->pass == PassKind::minmax_init ||
                program->pass == PassKind::minmax_reduce)
        << program->variant << " " << to_string(program->pass);
  }
  EXPECT_EQ(library.find("hard", Target::glsl450), nullptr);
  EXPECT_EQ(library.why_not_found("hard", Target::glsl450),
            "variant hard was built without the query form (its forms: function)");
  EXPECT_EQ(library.why_not_found("hard", Target::hlsl_dx9, PassKind::deferred),
            "variant hard was built without the deferred form (its forms: function)");
  EXPECT_EQ(library.why_not_found("screen_blur_r2", Target::glsl450),
            "no variant screen_blur_r2 in the library");
}

INSTANTIATE_TEST_SUITE_P(Embeddings, Embedded,
                         ::testing::Values(Embedding{"parts", &embed_test::library},
                                           Embedding{"whole", &embed_whole::library}),
                         [](const auto& param) { return std::string(param.param.name); });

TEST(EmbedLibrary, ANameThatIsNoIdentifierIsRefused) {
  const auto result = embed_library(built(), ::testing::TempDir(), {.name = "3d-shaders"});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().where, "--name");
  EXPECT_THAT(result.error().message, ::testing::HasSubstr("not a C++ identifier"));
}

TEST(EmbedLibrary, APartOutsideItsRangeIsRefused) {
  const auto part = embed_library(built(), ::testing::TempDir(), {.name = "x", .part = 4097});
  ASSERT_FALSE(part.ok());
  EXPECT_EQ(part.error().where, "--part");
  EXPECT_THAT(part.error().message, ::testing::HasSubstr("allowed: 1..4096"));
  const Status index = embed_part_index(::testing::TempDir(), "x", 0);
  ASSERT_FALSE(index.ok());
  EXPECT_EQ(index.error().where, "--parts");
}

}  // namespace
}  // namespace penumbra::testing
