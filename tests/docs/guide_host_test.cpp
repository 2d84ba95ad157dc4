// The Direct3D guides' code against penumbra_d3d_host.exe, the engine that
// verify's d3d9, d3d10 and d3d11 paths run (runtime/d3d/host): every
// Direct3D constant and every method the guides' C++ snippets use is one the
// host uses too, so a guide never tells an engine to do what no verified run
// did. The few calls the host has no need of are listed with why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace penumbra::testing {
namespace {

const std::filesystem::path kSourceDir = PENUMBRA_SOURCE_DIR;

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct GuideHost {
  std::string guide;               // docs/engines/<guide>.md
  std::vector<std::string> files;  // the host's sources for that runtime
};

const std::vector<GuideHost> kGuides = {
    {"d3d9", {"d3d9_device.cpp"}},
    {"d3d10", {"d3d10_device.cpp", "dxgi_device.hpp", "dxgi_names.cpp", "dxgi_names.hpp"}},
    {"d3d11", {"d3d11_device.cpp", "dxgi_device.hpp", "dxgi_names.cpp", "dxgi_names.hpp"}},
};

// Test logs name the guide.
void PrintTo(const GuideHost& guide, std::ostream* out) {
  *out << guide.guide << ".md";
}

// What a guide may show that the host does not do, and why.
const std::map<std::string, std::string> kNotTheHosts = {
    {"Release", "the host holds its objects in ComPtr"},
    {"GetBufferPointer", "the guides' D3DCompile alternative; the host loads the bytecode files"},
    {"GetBufferSize", "the guides' D3DCompile alternative; the host loads the bytecode files"},
    {"CopyResource", "d3d10.md's Direct3D 10.1 way to load a map; the host keeps to 10.0's rules"},
};

// The C++ fenced blocks of a guide.
std::string guide_code(const std::string& markdown) {
  static const std::regex block(R"(```cpp\n([\s\S]*?)```)");
  std::string code;
  for (auto it = std::sregex_iterator(markdown.begin(), markdown.end(), block);
       it != std::sregex_iterator(); ++it) {
    code += (*it)[1].str();
  }
  return code;
}

std::set<std::string> matches(const std::string& text, const std::regex& pattern, int group) {
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern);
       it != std::sregex_iterator(); ++it) {
    out.insert((*it)[group].str());
  }
  return out;
}

class GuideHostTest : public ::testing::TestWithParam<GuideHost> {};

TEST_P(GuideHostTest, TheGuidesCodeIsWhatTheVerifiedHostDoes) {
  const std::string code =
      guide_code(read(kSourceDir / "docs" / "engines" / (GetParam().guide + ".md")));
  ASSERT_FALSE(code.empty()) << GetParam().guide << ".md has no C++ snippet";
  std::string host;
  for (const std::string& file : GetParam().files) {
    host += read(kSourceDir / "runtime" / "d3d" / "host" / file);
  }
  ASSERT_FALSE(host.empty());
  static const std::regex constant(R"(\b(D3D[A-Z0-9]*_[A-Z0-9_]+|DXGI_FORMAT_[A-Z0-9_]+)\b)");
  static const std::regex method(R"((->|\.)([A-Z][A-Za-z0-9]+)\()");
  std::set<std::string> used = matches(code, constant, 1);
  used.merge(matches(code, method, 2));
  EXPECT_GT(used.size(), 10u);
  for (const std::string& name : used) {
    if (kNotTheHosts.contains(name)) continue;
    EXPECT_NE(host.find(name), std::string::npos)
        << GetParam().guide << ".md uses " << name << ", which penumbra_d3d_host never does";
  }
}

INSTANTIATE_TEST_SUITE_P(Direct3D, GuideHostTest, ::testing::ValuesIn(kGuides),
                         [](const auto& param_info) { return param_info.param.guide; });

}  // namespace
}  // namespace penumbra::testing
