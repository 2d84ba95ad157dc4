// Starting a Direct3D runtime's host without waiting for it: launch()
// returns with the host still booting, ready() waits for its device, and a
// host that cannot start fails every later call the same way.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "penumbra/d3d/engine.hpp"
#include "penumbra/d3d/wine_session.hpp"

namespace penumbra {
namespace {

std::shared_ptr<WineSession> session() {
  auto started = WineSession::start(WineSession::options_from_environment());
  EXPECT_TRUE(started) << started.error().to_string();
  return started ? *started : nullptr;
}

TEST(D3dEngineStart, LaunchReturnsBeforeTheDeviceAndReadyWaitsForIt) {
  const auto wine = session();
  ASSERT_TRUE(wine);
  D3dEngineOptions options;
  options.runtime = D3dRuntime::d3d11;
  auto engine = D3dEngine::launch(wine, options);
  ASSERT_TRUE(engine) << engine.error().to_string();
  // Nothing has read the host's answer yet.
  EXPECT_EQ((*engine)->description(), "");
  const Status ready = (*engine)->ready();
  ASSERT_TRUE(ready) << ready.error().to_string();
  EXPECT_NE((*engine)->description().find("Direct3D 11"), std::string::npos)
      << (*engine)->description();
  EXPECT_TRUE((*engine)->ready());  // at once, the second time
}

TEST(D3dEngineStart, AHostThatCannotStartFailsEveryCallTheSameWay) {
  const auto wine = session();
  ASSERT_TRUE(wine);
  const std::filesystem::path host = std::filesystem::temp_directory_path() /
                                     ("penumbra-not-a-host-" + std::to_string(::getpid()) + ".exe");
  std::ofstream(host) << "not a Windows program\n";
  D3dEngineOptions options;
  options.runtime = D3dRuntime::d3d9;
  options.host = host;
  auto engine = D3dEngine::launch(wine, options);
  const Status first = engine ? (*engine)->ready() : Status(engine.error());
  const Status second = engine ? (*engine)->ready() : Status(engine.error());
  std::filesystem::remove(host);
  ASSERT_TRUE(engine) << engine.error().to_string();  // Wine itself started
  ASSERT_FALSE(first);
  ASSERT_FALSE(second);
  EXPECT_EQ(second.error().to_string(), first.error().to_string());
}

TEST(D3dEngineStart, AHostThatDoesNotExistIsAnErrorAtLaunch) {
  const auto wine = session();
  ASSERT_TRUE(wine);
  D3dEngineOptions options;
  options.runtime = D3dRuntime::d3d10;
  options.host = "/nonexistent/penumbra_d3d_host.exe";
  auto engine = D3dEngine::launch(wine, options);
  ASSERT_FALSE(engine);
  EXPECT_EQ(engine.error().kind, Error::Kind::device);
  EXPECT_NE(engine.error().to_string().find("/nonexistent/penumbra_d3d_host.exe"),
            std::string::npos);
}

}  // namespace
}  // namespace penumbra
