// Finds the PCSS query for Direct3D 10 and Vulkan by technique and keys.
#include <cstdio>
#include <string>

#include "engine_shadows/shaders.hpp"

int main() {
  const penumbra::VariantKeys keys{
      .blocker_samples = 16, .pcf_samples = 16, .disk = "whitepaper16"};
  const auto* d3d10 =
      engine_shadows::find(penumbra::Technique::pcss, keys, penumbra::Target::hlsl_dx10);
  const auto* vulkan =
      engine_shadows::find(penumbra::Technique::pcss, keys, penumbra::Target::spirv);
  // glsl450 is in the manifest but not in the function's TARGETS.
  const auto* gl = engine_shadows::find(penumbra::Technique::pcss, keys, penumbra::Target::glsl450);
  if (d3d10 == nullptr || vulkan == nullptr || gl != nullptr || d3d10->fragment.text.empty() ||
      vulkan->fragment.spirv.empty() || d3d10->reflection.empty()) {
    std::fprintf(stderr, "embedded: the lookup did not give the programs built\n");
    return 1;
  }
  std::printf("embedded: %s, %zu programs, hlsl_dx10 query %zu chars of HLSL\n",
              std::string(d3d10->variant).c_str(), engine_shadows::library().programs().size(),
              d3d10->fragment.text.size());
  return 0;
}
