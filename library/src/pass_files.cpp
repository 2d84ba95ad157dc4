#include "penumbra/library/pass_files.hpp"

#include "penumbra/support/file.hpp"

namespace penumbra {

Result<const PassFiles*> pass_files(const LibraryVariant& variant, PassKind pass, Target target) {
  const auto by_pass = variant.passes.find(pass);
  if (by_pass == variant.passes.end() || !by_pass->second.contains(target)) {
    return make_error(Error::Kind::bad_input, variant.variant.name,
                      "the library has no " + std::string(to_string(pass)) + " pass for target " +
                          std::string(to_string(target)));
  }
  return &by_pass->second.at(target);
}

Result<std::filesystem::path> pass_stage_path(const Library& library, const LibraryVariant& variant,
                                              PassKind pass, Target target, ShaderStage stage) {
  auto files = pass_files(variant, pass, target);
  if (!files) return files.error();
  return library.root / (stage == ShaderStage::vertex ? (*files)->vert : (*files)->frag);
}

Result<PassReflection> pass_reflection(const LibraryVariant& variant, PassKind pass,
                                       Target target) {
  const auto by_pass = variant.reflection.find(pass);
  if (by_pass == variant.reflection.end() || !by_pass->second.contains(target)) {
    return make_error(Error::Kind::bad_input, variant.variant.name,
                      "index.json has no reflection." + std::string(to_string(pass)) + "." +
                          std::string(to_string(target)) + " to bind the pass by");
  }
  return by_pass->second.at(target);
}

Result<std::string> read_pass_file(const Library& library, const LibraryVariant& variant,
                                   PassKind pass, Target target, ShaderStage stage) {
  auto path = pass_stage_path(library, variant, pass, target, stage);
  if (!path) return path.error();
  return read_file(*path);
}

}  // namespace penumbra
