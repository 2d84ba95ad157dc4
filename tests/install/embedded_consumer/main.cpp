// Finds the PCSS query for Direct3D 10 and Vulkan by technique and keys, and
// its function form; the deferred form was not built, and the lookup says so.
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
  // FORMS query function: no deferred pass, and a function form.
  const std::string variant(d3d10->variant);
  const penumbra::shaders::Library& library = engine_shadows::library();
  const std::string why =
      library.why_not_found(variant, penumbra::Target::hlsl_dx10, penumbra::PassKind::deferred);
  if (library.find(variant, penumbra::Target::hlsl_dx10, penumbra::PassKind::deferred) ||
      why != "variant " + variant + " was built without the deferred form (its forms: query, " +
                 "function)" ||
      !engine_shadows::find_function(penumbra::Technique::pcss, keys,
                                     penumbra::Target::hlsl_dx10)) {
    std::fprintf(stderr, "embedded: the forms built are not the FORMS asked: %s\n", why.c_str());
    return 1;
  }
  std::printf("embedded: %s, %zu programs, hlsl_dx10 query %zu chars of HLSL\n",
              std::string(d3d10->variant).c_str(), engine_shadows::library().programs().size(),
              d3d10->fragment.text.size());
  return 0;
}
