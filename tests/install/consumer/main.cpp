// consumer OUT_DIR: builds a two-target library of one variant into OUT_DIR
// through the installed compiler library, and checks that it wrote files.
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace {

constexpr std::string_view kManifest =
    R"({"schema": 1, "targets": ["spirv", "glsl450"], "sets": [{"technique": "hard"}]})";

int fail(const std::string& message) {
  std::cerr << "consumer: " << message << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return fail("usage: consumer OUT_DIR");
  const std::filesystem::path out = argv[1];

  auto manifest = penumbra::parse_manifest(kManifest, "consumer manifest");
  if (!manifest) return fail(manifest.error().to_string());
  auto variants = penumbra::expand(*manifest);
  if (!variants) return fail(variants.error().to_string());
  if (variants->size() != 1) return fail("expected one variant");

  auto summary = penumbra::build_library(*variants, out, penumbra::BuildOptions{},
                                         penumbra::ignore_diagnostics());
  if (!summary) return fail(summary.error().to_string());
  if (summary->variants != 1 || summary->files == 0) return fail("nothing was built");
  if (!std::filesystem::is_regular_file(out / "index.json")) return fail("no index.json");

  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(out)) {
    if (entry.is_regular_file()) ++files;
  }
  std::cout << "consumer: " << (*variants)[0].name << ": " << summary->files << " shader files, "
            << files << " files in " << out.string() << "\n";
  return 0;
}
