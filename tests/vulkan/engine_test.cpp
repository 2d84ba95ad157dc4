// Engine creation and device selection.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "test_programs.hpp"

namespace penumbra {
namespace {

TEST(EngineTest, PicksLavapipeByDefault) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  const DeviceInfo& info = engine->device_info();
  EXPECT_NE(info.name.find("llvmpipe"), std::string::npos) << info.name;
  EXPECT_NE(info.driver.find("llvmpipe"), std::string::npos) << info.driver;
  EXPECT_EQ(info.sub_texel_precision_bits, 8u);
  EXPECT_EQ(info.api_version >> 22, 1u);             // variant 0, major 1
  EXPECT_GE((info.api_version >> 12) & 0x3ffu, 2u);  // minor >= 2
}

TEST(EngineTest, SelectsByIndexOrCaseInsensitiveName) {
  for (const char* selector : {"0", "LLVMpipe"}) {
    auto engine = Engine::create({selector, false}, ignore_diagnostics());
    ASSERT_TRUE(engine) << selector << ": " << engine.error().to_string();
    EXPECT_NE((*engine)->device_info().name.find("llvmpipe"), std::string::npos);
  }
}

TEST(EngineTest, UnknownDeviceListsTheAvailableOnes) {
  auto engine = Engine::create({"no-such-gpu", false}, ignore_diagnostics());
  ASSERT_FALSE(engine);
  EXPECT_EQ(engine.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(engine.error().where, "device 'no-such-gpu'");
  EXPECT_NE(engine.error().message.find("no Vulkan device matches"), std::string::npos);
  EXPECT_NE(engine.error().message.find("0: llvmpipe"), std::string::npos)
      << engine.error().message;
}

TEST(EngineTest, OutOfRangeIndexListsTheAvailableOnes) {
  auto engine = Engine::create({"99", false}, ignore_diagnostics());
  ASSERT_FALSE(engine);
  EXPECT_NE(engine.error().message.find("0: llvmpipe"), std::string::npos)
      << engine.error().message;
}

// Sets (or, with nullptr, unsets) an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) {
      setenv(name, value, 1);
    } else {
      unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(EngineTest, NoDriverIsAClearDeviceError) {
  const ScopedEnv no_driver("VK_ICD_FILENAMES", "/nonexistent/penumbra_icd.json");
  const ScopedEnv no_newer_name("VK_DRIVER_FILES", nullptr);  // it would take precedence
  auto engine = Engine::create({}, ignore_diagnostics());
  ASSERT_FALSE(engine);
  EXPECT_EQ(engine.error().kind, Error::Kind::device);
  EXPECT_NE(engine.error().message.find("no Vulkan device found (is mesa-vulkan-drivers "
                                        "installed? VK_ICD_FILENAMES=/nonexistent/"),
            std::string::npos)
      << engine.error().message;
}

}  // namespace
}  // namespace penumbra
