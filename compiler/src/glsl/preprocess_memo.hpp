// The texts a build's preprocessing made last, and what each depended on, so
// that a job whose variant.glsl differs only in macros no file it reads
// mentions takes an earlier job's text: the three GLSL targets of a pass
// differ only in PENUMBRA_TARGET_*, which the shader library never tests.
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/compiler/shaderlib_source.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra {

// What preprocessing one pass made: its text and the shaderlib files it read.
struct Preprocessed {
  std::string text;
  std::vector<std::string> inputs;
};

// The identifiers (C-like names) of `text`, comments included: a superset of
// the macros its preprocessing can expand or test.
std::set<std::string> identifiers_of(std::string_view text);

// `header` as a key for a pass whose files mention only `mentioned`: the
// #define lines of other names and the comment lines are blanked (kept as
// empty lines, so that line numbers stay the same).
std::string header_key(std::string_view header, const std::set<std::string>& mentioned);

// The last `capacity` texts, found by stage, source and header; safe from
// any thread. A job takes an earlier one's text only when their headers
// agree on every macro any file read for that stage and source names (its
// #define line present and the same in both), and on every other line: the
// preprocessor then reads the same files and expands the same tokens.
class PreprocessMemo {
 public:
  PreprocessMemo(std::size_t capacity, const ShaderlibSource& shaderlib)
      : capacity_(capacity), shaderlib_(shaderlib) {}
  std::optional<Preprocessed> find(ShaderStage stage, const std::string& source,
                                   const std::string& header) const;
  // `made` was preprocessed from `source` with `header`.
  void add(ShaderStage stage, const std::string& source, const std::string& header,
           const Preprocessed& made);

 private:
  using Source = std::pair<ShaderStage, std::string>;
  const std::set<std::string>& file_identifiers(const std::string& path);  // locked

  std::size_t capacity_;
  const ShaderlibSource& shaderlib_;
  mutable std::mutex mutex_;
  // What the files read for each (stage, source) so far mention, the
  // header's define values and other lines included.
  struct Mentioned {
    std::set<std::string> names;
    std::set<std::string> files;  // whose names are in
  };
  std::map<Source, Mentioned> mentioned_;
  std::map<std::string, std::set<std::string>> files_;      // a shaderlib file's identifiers
  std::deque<std::pair<std::string, Preprocessed>> texts_;  // by key, oldest first
};

}  // namespace penumbra
