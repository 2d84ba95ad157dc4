#include "targets/dx10_comparison_textures.hpp"

#include "penumbra/model/shader_contract.hpp"

namespace penumbra {

std::string dx10_comparison_textures_as_scalar(const std::string& hlsl, std::string_view prefix) {
  std::string out = hlsl;
  for (const TextureDescription& texture : all_textures()) {
    if (!texture.sampler.comparison) continue;
    const std::string name = std::string(prefix) + std::string(texture.name);
    for (const std::string type : {"Texture2D", "Texture2DArray"}) {
      const std::string vector = type + "<float4> " + name + " :";
      const std::string scalar = type + "<float> " + name + " :";
      for (auto at = out.find(vector); at != std::string::npos; at = out.find(vector, at)) {
        out.replace(at, vector.size(), scalar);
      }
    }
  }
  return out;
}

}  // namespace penumbra
