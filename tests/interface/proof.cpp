#include "proof.hpp"

#include <fstream>
#include <sstream>

namespace penumbra::testing {
namespace {

std::string site(const LibraryVariant& variant, PassKind pass, Target target) {
  return variant.variant.name + ", " + std::string(to_string(pass)) + " pass, " +
         std::string(to_string(target));
}

}  // namespace

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

Result<std::string> read_pass_file(const Library& library, const LibraryVariant& variant,
                                   PassKind pass, Target target, ShaderStage stage) {
  const auto by_pass = variant.passes.find(pass);
  if (by_pass == variant.passes.end() || !by_pass->second.contains(target)) {
    return proof_error(variant, pass, target, "index.json lists no files for this pass");
  }
  const PassFiles& files = by_pass->second.at(target);
  const auto path = library.root / (stage == ShaderStage::vertex ? files.vert : files.frag);
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(Error::Kind::io, path.string(), "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace penumbra::testing
