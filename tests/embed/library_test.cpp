// penumbra::shaders::Library over hand-written parts: lookups across parts,
// the order of programs() and functions(), and SPIR-V read out of an
// unaligned blob.
#include "penumbra/shaders/library.hpp"

#include <gtest/gtest.h>

namespace penumbra::shaders {
namespace {

using namespace std::string_view_literals;

// "x" pads the SPIR-V so that it starts at an odd offset.
constexpr std::string_view kFirstBlob[] = {"vert-afrag-a"sv, "x\x03\x02\x23\x07"sv};
constexpr EmbeddedProgram kFirst[] = {
    {"a", Target::glsl450, PassKind::query, {0, 6}, {6, 6}, {}, {}, "", "", {}},
    {"c", Target::spirv, PassKind::query, {13, 4}, {13, 4}, {}, {}, "", "", {}},
};
constexpr std::string_view kSecondBlob[] = {"{\"b\":1}"sv, "float f();"sv};
constexpr EmbeddedProgram kSecond[] = {
    {"b", Target::hlsl_dx10, PassKind::depth, {0, 0}, {0, 0}, {}, {0, 7}, "", "ps_4_0", {0, 7}},
};
constexpr EmbeddedFunction kSecondFunctions[] = {
    {"b", Target::glsl330, {7, 10}, {0, 7}},
    {"b", Target::essl300, {7, 10}, {0, 7}},
};
// Bit Form of each: a in the query and function forms, c in the query form,
// b in the deferred and function forms.
constexpr EmbeddedVariant kFirstVariants[] = {{"a", 5u}, {"c", 1u}};
constexpr EmbeddedVariant kSecondVariants[] = {{"b", 6u}};
constexpr EmbeddedPart kParts[] = {{kFirstBlob, kFirst, {}, kFirstVariants},
                                   {kSecondBlob, {}},
                                   {kSecondBlob, kSecond, kSecondFunctions, kSecondVariants}};

TEST(ShadersLibrary, FindsEachProgramInItsPart) {
  const Library library(kParts);
  EXPECT_EQ(library.size(), 3u);
  const Program* a = library.find("a", Target::glsl450);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->vertex.text, "vert-a");
  EXPECT_EQ(a->fragment.text, "frag-a");
  const Program* b = library.find("b", Target::hlsl_dx10, PassKind::depth);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->fragment.profile, "ps_4_0");
  EXPECT_EQ(b->fragment.bytecode.size(), 7u);
  EXPECT_EQ(b->reflection, "{\"b\":1}");
  const Program* c = library.find("c", Target::spirv);
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->fragment.spirv.size(), 1u);
  EXPECT_EQ(c->fragment.spirv[0], 0x07230203u);
  EXPECT_EQ(library.find("b", Target::hlsl_dx10), nullptr);  // the query pass
  EXPECT_EQ(library.find("d", Target::spirv), nullptr);
  EXPECT_EQ(library.find("b", Target::hlsl_dx10, PassKind::depth), b);  // built once
}

TEST(ShadersLibrary, FindsEachFunctionFormInItsPart) {
  const Library library(kParts);
  const Function* glsl = library.find_function("b", Target::glsl330);
  ASSERT_NE(glsl, nullptr);
  EXPECT_EQ(glsl->text, "float f();");
  EXPECT_EQ(glsl->reflection, "{\"b\":1}");
  ASSERT_NE(library.find_function("b", Target::essl300), nullptr);
  EXPECT_EQ(library.find_function("b", Target::glsl450), nullptr);
  EXPECT_EQ(library.find_function("a", Target::glsl330), nullptr);
  ASSERT_EQ(library.functions().size(), 2u);
  EXPECT_EQ(library.functions()[0]->target, Target::glsl330);  // in kAllTargets order
}

// A lookup that finds nothing says why: a form not built is named with the
// forms the variant has.
TEST(ShadersLibrary, SaysWhyAProgramOrFunctionIsNotThere) {
  const Library library(kParts);
  EXPECT_EQ(library.forms("a"), (std::vector<Form>{Form::query, Form::function}));
  EXPECT_EQ(library.forms("b"), (std::vector<Form>{Form::deferred, Form::function}));
  EXPECT_EQ(library.forms("d"), std::vector<Form>{});
  EXPECT_EQ(library.why_not_found("a", Target::glsl450), "");
  EXPECT_EQ(library.why_not_found("b", Target::hlsl_dx10),
            "variant b was built without the query form (its forms: deferred, function)");
  EXPECT_EQ(library.why_not_found("a", Target::glsl450, PassKind::deferred),
            "variant a was built without the deferred form (its forms: query, function)");
  EXPECT_EQ(library.why_not_found("a", Target::spirv),
            "variant a has no query pass for target spirv");
  EXPECT_EQ(library.why_not_found("c", Target::spirv, PassKind::depth),
            "variant c has no depth pass for target spirv");
  EXPECT_EQ(library.why_not_found("d", Target::spirv), "no variant d in the library");
  EXPECT_EQ(library.why_no_function("b", Target::glsl330), "");
  EXPECT_EQ(library.why_no_function("c", Target::glsl330),
            "variant c was built without the function form (its forms: query)");
  EXPECT_EQ(library.why_no_function("b", Target::glsl450),
            "variant b has no function form for target glsl450");
  EXPECT_EQ(library.why_no_function("e", Target::glsl450), "no variant e in the library");
}

TEST(ShadersLibrary, ListsProgramsInOrderAcrossParts) {
  const Library library(kParts);
  std::string order;
  for (const Program* p : library.programs()) order += p->variant;
  EXPECT_EQ(order, "abc");
}

}  // namespace
}  // namespace penumbra::shaders
