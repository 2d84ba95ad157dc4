#include "penumbra/compiler/targets.hpp"
#include "penumbra/support/file.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status WriteStage::process(ShaderJob& job) const {
  const std::filesystem::path path = root_ / job.output_path;
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return make_error(Error::Kind::io, path.parent_path().string(), ec.message());
  if (traits(job.target).is_text) {
    // GLSL ES requires #version to be the very first line: the banner follows it.
    std::string text = job.text;
    std::size_t at = 0;
    if (text.rfind("#version", 0) == 0) {
      if (text.find('\n') == std::string::npos) text += '\n';
      at = text.find('\n') + 1;
    }
    text.insert(at, "// " + job.banner() + "\n");
    return write_file(path, text);
  }
  return write_file(path, {reinterpret_cast<const char*>(job.spirv.data()),
                           job.spirv.size() * sizeof(std::uint32_t)});
}

}  // namespace penumbra
