#include <nlohmann/json.hpp>

#include "penumbra/spirv/reflection.hpp"

namespace penumbra {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BlockMember, name, offset, size)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(UniformBlock, type_name, instance_name, set, binding, size,
                                   members)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SampledImage, name, set, binding, comparison)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SeparateImage, name, set, binding, depth)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SeparateSampler, name, set, binding, image, comparison)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StageVariable, name, location, components)

void to_json(nlohmann::json& j, const ShaderInterface& iface) {
  j = nlohmann::json{{"stage", iface.stage == ShaderStage::vertex ? "vertex" : "fragment"},
                     {"entry_point", iface.entry_point},
                     {"uniform_blocks", iface.uniform_blocks},
                     {"sampled_images", iface.sampled_images},
                     {"separate_images", iface.separate_images},
                     {"separate_samplers", iface.separate_samplers},
                     {"inputs", iface.inputs},
                     {"outputs", iface.outputs},
                     {"builtin_outputs", iface.builtin_outputs}};
}

void from_json(const nlohmann::json& j, ShaderInterface& iface) {
  iface.stage = j.at("stage") == "vertex" ? ShaderStage::vertex : ShaderStage::fragment;
  j.at("entry_point").get_to(iface.entry_point);
  j.at("uniform_blocks").get_to(iface.uniform_blocks);
  j.at("sampled_images").get_to(iface.sampled_images);
  // Absent from records written before the text targets ran on the runtime.
  iface.separate_images = j.value("separate_images", std::vector<SeparateImage>());
  iface.separate_samplers = j.value("separate_samplers", std::vector<SeparateSampler>());
  iface.builtin_outputs = j.value("builtin_outputs", std::vector<std::string>());
  j.at("inputs").get_to(iface.inputs);
  j.at("outputs").get_to(iface.outputs);
}

}  // namespace penumbra
