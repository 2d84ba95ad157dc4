// The default library's variants (permutations/default.json) as every test
// suite reads them, test names made from them, libraries built from
// variants into temporary directories, and the targets a suite covers.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/build.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra::testing {

// The variants of permutations/default.json, loaded once. A manifest that
// cannot be loaded aborts the test binary with the error (its tests would
// otherwise not exist).
const std::vector<Variant>& default_variants();

// The default variant `name`, or null.
const Variant* find_default_variant(std::string_view name);

// The default variants' names, in the manifest's order (test parameters).
std::vector<std::string> default_variant_names();

// The targets with text (every one but spirv), and the HLSL targets, in
// kAllTargets order: chosen by traits(), so suites cover a new target.
std::vector<Target> text_targets();
std::vector<Target> hlsl_targets();

// `name` as a test name: every character but letters and digits made '_'.
std::string test_name(std::string name);

// A library built with build_library into a directory of its own under the
// test temporary directory and read back with load_library; the directory
// is removed with the object.
class TemporaryLibrary {
 public:
  // `variants`, each for those of its targets that are in `targets` (all
  // of them when `targets` is empty); the error is the build's or the
  // read's.
  static Result<std::unique_ptr<TemporaryLibrary>> build(std::vector<Variant> variants,
                                                         const std::vector<Target>& targets = {},
                                                         const BuildOptions& options = {});

  ~TemporaryLibrary();
  TemporaryLibrary(const TemporaryLibrary&) = delete;
  TemporaryLibrary& operator=(const TemporaryLibrary&) = delete;

  const Library& library() const { return library_; }

 private:
  explicit TemporaryLibrary(std::filesystem::path root) : root_(std::move(root)) {}

  std::filesystem::path root_;
  Library library_;
};

// The library of the default variant `name` alone, for those of its targets
// in `targets` (all when empty); the error names a variant the manifest
// lacks.
Result<std::unique_ptr<TemporaryLibrary>> build_default_variant(
    std::string_view name, const std::vector<Target>& targets = {});

}  // namespace penumbra::testing
