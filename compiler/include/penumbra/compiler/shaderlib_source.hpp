// Where the build reads the shader library's files (shaderlib/: common/,
// techniques/, passes/) from: the copy embedded into the compiler, or a
// folder with the same layout (penumbra build --shaderlib DIR).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra {

class ShaderlibSource {
 public:
  virtual ~ShaderlibSource() = default;
  // The text of a file by its path relative to shaderlib/
  // ("passes/query.frag"); nullopt when there is no such file.
  virtual std::optional<std::string> read(std::string_view path) const = 0;
  // Where that file is, for messages and depfiles: "shaderlib/<path>" for the
  // embedded copy, DIR/<path> for a folder.
  virtual std::string location(std::string_view path) const = 0;
  // Whether location() names real files (a folder), which a build system can
  // watch; the embedded copy's are only names.
  virtual bool on_disk() const = 0;
};

// The copy embedded into the compiler at its build time (the default).
std::shared_ptr<const ShaderlibSource> embedded_shaderlib();

// The files under `dir`. A bad_input error located at `dir` when it is not a
// directory or has no passes/query.frag (not a shader library).
Result<std::shared_ptr<const ShaderlibSource>> shaderlib_directory(
    const std::filesystem::path& dir);

}  // namespace penumbra
