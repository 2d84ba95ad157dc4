// With EngineOptions::validation the Khronos validation layer checks every
// call: the runtime's own use of Vulkan must be clean, and a validation error
// must fail the call and reach the diagnostics.
#include <gtest/gtest.h>

#include <mutex>
#include <string>
#include <vector>

#include "test_programs.hpp"

namespace penumbra {
namespace {

const test::TestLight kLight;

class ValidationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto engine = Engine::create({"", true}, [this](const Diagnostic& diagnostic) {
      const std::lock_guard lock(mutex_);
      diagnostics_.push_back(diagnostic);
    });
    ASSERT_TRUE(engine) << engine.error().to_string();
    engine_ = std::move(*engine);
    for (const Diagnostic& diagnostic : diagnostics_) {
      if (diagnostic.message.find("is not installed") != std::string::npos) {
        GTEST_SKIP() << diagnostic.message;
      }
    }
  }

  std::vector<Diagnostic> validation_messages() {
    const std::lock_guard lock(mutex_);
    std::vector<Diagnostic> messages;
    for (const Diagnostic& diagnostic : diagnostics_) {
      if (diagnostic.where == "vulkan validation") messages.push_back(diagnostic);
    }
    return messages;
  }

  std::mutex mutex_;
  std::vector<Diagnostic> diagnostics_;
  std::unique_ptr<Engine> engine_;
};

TEST_F(ValidationTest, EveryOperationIsClean) {
  const std::vector<std::array<float, 3>> triangle{{-1, -1, 12}, {1, -1, 12}, {0, 1, 12}};
  auto rendered = engine_->render_depth(test::depth_program(), triangle, 8, 8,
                                        test::make_params(kLight, 8, 8, 8, 8));
  ASSERT_TRUE(rendered) << rendered.error().to_string();
  auto uploaded = engine_->upload_shadow_map(FloatImage(8, 8, 1, 0.5f));
  ASSERT_TRUE(uploaded) << uploaded.error().to_string();
  EXPECT_TRUE(engine_->read_shadow_map(**rendered));
  const FloatImage receivers(4, 3, 4, 0.25f);
  for (const PassProgram& program : {test::compare_program(), test::point_program()}) {
    auto visibility =
        engine_->run_query(program, **uploaded, receivers, test::make_params(kLight, 8, 8, 4, 3));
    EXPECT_TRUE(visibility) << visibility.error().to_string();
  }
  for (const Diagnostic& message : validation_messages()) ADD_FAILURE() << message.message;
}

// A reflection record (and module view) hiding the vertex stage's use of
// ShadowParams gives a set layout the vertex shader cannot see: an error
// only the layer detects.
TEST_F(ValidationTest, AValidationErrorFailsTheCall) {
  PassProgram program = test::depth_program();
  program.vert.iface.uniform_blocks.clear();
  program.reflection.vert.blocks.clear();
  auto map = engine_->render_depth(program, {}, 4, 4, test::make_params(kLight, 4, 4, 4, 4));
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().kind, Error::Kind::device);
  EXPECT_EQ(map.error().where, "vulkan validation");
  const auto messages = validation_messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_EQ(messages.front().severity, Severity::error);
}

}  // namespace
}  // namespace penumbra
