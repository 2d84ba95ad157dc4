#include <fstream>

#include "penumbra/compiler/targets.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status WriteStage::process(ShaderJob& job) const {
  const std::filesystem::path path = root_ / job.output_path;
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  std::ofstream file(path, std::ios::binary);
  if (traits(job.target).is_text) {
    // GLSL ES requires #version to be the very first line: the banner follows it.
    std::string text = job.text;
    const std::size_t at = text.rfind("#version", 0) == 0 ? text.find('\n') + 1 : 0;
    text.insert(at, "// " + job.banner() + "\n");
    file << text;
  } else {
    file.write(reinterpret_cast<const char*>(job.spirv.data()),
               static_cast<std::streamsize>(job.spirv.size() * sizeof(std::uint32_t)));
  }
  file.close();
  if (!file) {
    return make_error(Error::Kind::io, path.string(), "could not write the shader file");
  }
  return {};
}

}  // namespace penumbra
