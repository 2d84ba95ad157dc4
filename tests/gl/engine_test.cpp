// Creating GL engines headless: the default display, EGL device selectors,
// and engines that share one display.
#include <EGL/egl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "gl_fixture.hpp"

namespace penumbra::testing {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Runs the hard variant's glsl450 pass on the first scene.
Result<FloatImage> run_hard(GlEngine& engine) {
  auto variant = find_default_variant("hard");
  if (!variant) return make_error(Error::Kind::internal, "test", "no variant hard");
  auto text = emitted_pass(*variant, Target::glsl450, PassKind::query);
  if (!text) return text.error();
  const SceneInputs inputs = any_scene_inputs();
  auto output =
      engine.run_query({text->view()}, inputs.normalized_depth, inputs.receivers, inputs.params);
  if (!output) return output.error();
  return std::move(output->visibility);
}

TEST(GlEngineTest, DefaultDisplayIsLlvmpipeWithGl45Core) {
  std::vector<Diagnostic> notes;
  auto engine =
      GlEngine::create({}, [&](const Diagnostic& diagnostic) { notes.push_back(diagnostic); });
  ASSERT_TRUE(engine.ok()) << engine.error().to_string();
  const GlInfo& info = (*engine)->info();
  EXPECT_NE(lower(info.renderer).find("llvmpipe"), std::string::npos) << info.renderer;
  EXPECT_TRUE(info.version.starts_with("4.5") || info.version.starts_with("4.6")) << info.version;
  EXPECT_NE(info.version.find("Core Profile"), std::string::npos) << info.version;
  EXPECT_TRUE(info.glsl_version.starts_with("4.")) << info.glsl_version;
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].message.find(info.renderer), std::string::npos) << notes[0].message;
}

TEST(GlEngineTest, SelectsEglDevicesByIndexAndRenderer) {
  for (const std::string selector : {"0", "LLVMpipe"}) {
    auto engine = GlEngine::create({.device = selector}, ignore_diagnostics());
    ASSERT_TRUE(engine.ok()) << selector << ": " << engine.error().to_string();
    EXPECT_NE(lower((*engine)->info().renderer).find("llvmpipe"), std::string::npos);
    auto visibility = run_hard(**engine);
    EXPECT_TRUE(visibility.ok()) << selector << ": " << visibility.error().to_string();
  }
}

TEST(GlEngineTest, UnmatchedSelectorListsTheDevices) {
  for (const std::string selector : {"no-such-gpu", "99"}) {
    auto engine = GlEngine::create({.device = selector}, ignore_diagnostics());
    ASSERT_FALSE(engine.ok()) << selector;
    EXPECT_EQ(engine.error().kind, Error::Kind::bad_input);
    EXPECT_NE(engine.error().where.find(selector), std::string::npos) << engine.error().where;
    EXPECT_NE(lower(engine.error().message).find("0: llvmpipe"), std::string::npos)
        << engine.error().message;
  }
}

// Engines share the surfaceless display: destroying one must not terminate
// it under the other.
TEST(GlEngineTest, EnginesOnOneDisplayOutliveEachOther) {
  auto first = make_gl_engine();
  auto second = make_gl_engine();
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  first.reset();
  auto visibility = run_hard(*second);
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  first = make_gl_engine();
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(run_hard(*first).ok());
}

// Each call restores the thread's EGL state: no context is left current and
// the bound API is the one the caller had.
TEST(GlEngineTest, CallsLeaveTheThreadsEglStateAsTheyFoundIt) {
  auto engine = make_gl_engine();
  ASSERT_NE(engine, nullptr);
  ASSERT_EQ(eglBindAPI(EGL_OPENGL_ES_API), EGL_TRUE);
  ASSERT_TRUE(run_hard(*engine).ok());
  EXPECT_EQ(eglQueryAPI(), static_cast<EGLenum>(EGL_OPENGL_ES_API));
  ASSERT_EQ(eglBindAPI(EGL_OPENGL_API), EGL_TRUE);
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
}

}  // namespace
}  // namespace penumbra::testing
