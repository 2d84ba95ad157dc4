#include "penumbra/vulkan/embedded_program.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "penumbra/spirv/reflection.hpp"

namespace penumbra {
namespace {

Result<StageCode> reflected(std::span<const std::uint32_t> words, const std::string& where) {
  auto iface = reflect(words);
  if (!iface) return make_error(Error::Kind::compile, where, iface.error().message);
  return StageCode{std::vector<std::uint32_t>(words.begin(), words.end()), std::move(*iface)};
}

}  // namespace

Result<PassProgram> embedded_program(const shaders::Program& program) {
  const std::string where = std::string(program.variant) + " " +
                            std::string(to_string(program.target)) + " " +
                            std::string(to_string(program.pass)) + " pass";
  // Only spirv holds words the device runs as they are; the other targets'
  // text goes through glslang first, which load_executable does from files.
  if (program.target != Target::spirv) {
    return make_error(Error::Kind::bad_input, where,
                      "only spirv programs run as embedded (this one is " +
                          std::string(to_string(program.target)) +
                          " text; compile it with compile_target_text)");
  }
  PassProgram out;  // target spirv: no Direct3D viewport or GL clip depth to reproduce
  try {
    out.reflection = nlohmann::json::parse(program.reflection).get<PassReflection>();
  } catch (const nlohmann::json::exception& e) {
    return make_error(Error::Kind::bad_input, where,
                      std::string("the embedded reflection record cannot be read: ") + e.what());
  }
  PENUMBRA_TRY_ASSIGN(out.vert, reflected(program.vertex.spirv, where + " (vertex stage)"));
  PENUMBRA_TRY_ASSIGN(out.frag, reflected(program.fragment.spirv, where + " (fragment stage)"));
  return out;
}

}  // namespace penumbra
