#include "proof.hpp"

namespace penumbra::testing {
namespace {

std::string site(const LibraryVariant& variant, PassKind pass, Target target) {
  return variant.variant.name + ", " + std::string(to_string(pass)) + " pass, " +
         std::string(to_string(target));
}

void reflected_stage(std::string_view stage, const StageBindings& bindings, const FactStyle& style,
                     Facts& facts) {
  for (const BlockBinding& block : bindings.blocks) {
    const std::string key = std::string(stage) + " block " + block.name;
    facts[key] =
        slot_text(style, block.set, block.binding) + ", " + std::to_string(block.size) + " bytes";
    for (const ConstantBinding& member : block.members) {
      facts[key + " member " + member.name] =
          member_text(style, member.type, member.offset, member.size);
    }
  }
  for (const ConstantBinding& uniform : bindings.uniforms) {
    facts[std::string(stage) + " uniform " + uniform.name] = uniform.type;
  }
  for (const TextureBinding& texture : bindings.textures) {
    facts[std::string(stage) + " texture " + texture.name] =
        slot_text(style, texture.set, texture.binding) + ", " +
        texture_text(texture.type, texture.sampler.state.comparison);
  }
}

}  // namespace

std::string slot_text(const FactStyle& style, std::optional<std::uint32_t> set,
                      std::optional<std::uint32_t> binding) {
  if (!binding) binding = style.unset_binding;
  const std::string text = "binding " + (binding ? std::to_string(*binding) : "-");
  if (!style.with_set) return text;
  return "set " + (set ? std::to_string(*set) : "-") + ", " + text;
}

std::string texture_text(std::string_view type, bool comparison) {
  return std::string(type) + (comparison ? ", comparison" : ", no comparison");
}

std::string member_text(const FactStyle& style, std::string_view type,
                        std::optional<std::uint32_t> offset, std::uint32_t size) {
  std::string text = std::string(type) + " at " + (offset ? std::to_string(*offset) : "-");
  if (style.member_sizes) text += ", " + std::to_string(size) + " bytes";
  return text;
}

std::string input_text(std::optional<std::uint32_t> location, std::uint32_t components,
                       std::string_view format) {
  return "location " + (location ? std::to_string(*location) : "-") + ", " +
         std::to_string(components) + " components, " + std::string(format);
}

Facts reflected_facts(const PassReflection& pass, const FactStyle& style) {
  Facts facts;
  reflected_stage("vert", pass.vert, style, facts);
  reflected_stage("frag", pass.frag, style, facts);
  for (const VertexAttribute& input : pass.vertex_inputs) {
    facts["vert input " + input.name] = input_text(input.location, input.components, input.format);
  }
  for (const RenderTarget& target : pass.render_targets) {
    facts["frag output " + target.name] = "location " + std::to_string(target.index);
  }
  return facts;
}

Error proof_error(const LibraryVariant& variant, PassKind pass, Target target,
                  std::string message) {
  return make_error(Error::Kind::compile, site(variant, pass, target), std::move(message));
}

Status compare_facts(const LibraryVariant& variant, PassKind pass, Target target,
                     std::string_view parser, const Facts& reflected, const Facts& observed) {
  std::string differences;
  for (const auto& [entry, said] : reflected) {
    const auto seen = observed.find(entry);
    if (seen == observed.end()) {
      differences += "\n  " + entry + ": in the reflection (" + said + ") but not in the text";
    } else if (seen->second != said) {
      differences += "\n  " + entry + ": the reflection says '" + said + "', " +
                     std::string(parser) + " says '" + seen->second + "'";
    }
  }
  for (const auto& [entry, seen] : observed) {
    if (!reflected.contains(entry)) {
      differences += "\n  " + entry + ": " + std::string(parser) + " reports it (" + seen +
                     ") but the reflection lacks it";
    }
  }
  if (differences.empty()) return {};
  return proof_error(variant, pass, target, "the reflection and the text differ:" + differences);
}

Result<const PassReflection*> reflection_of(const LibraryVariant& variant, PassKind pass,
                                            Target target) {
  const auto by_pass = variant.reflection.find(pass);
  if (by_pass != variant.reflection.end()) {
    const auto by_target = by_pass->second.find(target);
    if (by_target != by_pass->second.end()) return &by_target->second;
  }
  return proof_error(variant, pass, target, "index.json has no reflection of this pass");
}

}  // namespace penumbra::testing
