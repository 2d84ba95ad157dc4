// The environment a Wine session gives its hosts: wined3d's command-stream
// thread off by default, and a user's own WINE_D3D_CONFIG left to them.
#include "penumbra/d3d/wine_session.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace penumbra {
namespace {

// A session on a prefix and display of its own, which start() only names:
// it starts no Xvfb and runs no Wine.
std::shared_ptr<WineSession> named_session() {
  auto session = WineSession::start({.prefix = "/nonexistent/prefix", .display = ":99"});
  EXPECT_TRUE(session) << session.error().message;
  return session ? *session : nullptr;
}

TEST(WineSessionEnvironment, HostsRunWithoutWined3dsCommandStreamThread) {
  ::unsetenv("WINE_D3D_CONFIG");
  const auto session = named_session();
  ASSERT_TRUE(session);
  const auto environment = session->environment();
  ASSERT_TRUE(environment.contains("WINE_D3D_CONFIG"));
  EXPECT_EQ(environment.at("WINE_D3D_CONFIG"), "csmt=0x0");
  EXPECT_EQ(environment.at("WINEPREFIX"), "/nonexistent/prefix");
  EXPECT_EQ(environment.at("DISPLAY"), ":99");
}

TEST(WineSessionEnvironment, AUsersWined3dSettingsAreInherited) {
  ::setenv("WINE_D3D_CONFIG", "renderer=gl", 1);
  const auto session = named_session();
  // Not set over the user's: the host inherits this process's value.
  const bool set_over = session && session->environment().contains("WINE_D3D_CONFIG");
  ::unsetenv("WINE_D3D_CONFIG");
  ASSERT_TRUE(session);
  EXPECT_FALSE(set_over);
}

}  // namespace
}  // namespace penumbra
