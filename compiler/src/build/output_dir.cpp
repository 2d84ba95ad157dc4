// A library or report folder is replaced wholesale, so only one that penumbra
// wrote may be: never a user's folder that merely holds a file named
// index.json or report.json.
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "penumbra/compiler/build.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// Reads a marker only up to its top-level "generator": in index.json it comes early,
// and the variants after it can be megabytes. Any other shape stops it too.
struct GeneratorReader {
  using json = nlohmann::json;
  int depth = 0;
  bool at_generator = false;  // the next value is the top-level "generator"
  std::optional<std::string> generator;

  bool scalar() { return !at_generator; }
  bool null() { return scalar(); }
  bool boolean(bool) { return scalar(); }
  bool number_integer(json::number_integer_t) { return scalar(); }
  bool number_unsigned(json::number_unsigned_t) { return scalar(); }
  bool number_float(json::number_float_t, const json::string_t&) { return scalar(); }
  bool binary(json::binary_t&) { return scalar(); }
  bool string(json::string_t& value) {
    if (at_generator) generator = value;
    return !at_generator;
  }
  bool start_object(std::size_t) { return !at_generator && ++depth > 0; }
  bool end_object() { return --depth >= 0; }
  bool start_array(std::size_t) { return !at_generator && depth++ > 0; }
  bool end_array() { return --depth >= 0; }
  bool key(json::string_t& name) {
    at_generator = depth == 1 && name == "generator";
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
    return false;
  }
};

// A folder penumbra wrote: its marker is a JSON object whose top-level
// "generator" is "penumbra <version>".
bool written_by_penumbra(const fs::path& marker) {
  std::ifstream in(marker, std::ios::binary);
  if (!in) return false;
  GeneratorReader reader;
  nlohmann::json::sax_parse(in, &reader);
  return reader.generator && reader.generator->starts_with("penumbra ");
}

}  // namespace

Status check_replaceable_directory(const fs::path& dir, const OutputKind& kind) {
  const std::string allowed = "allowed: a missing or empty directory, or a " +
                              std::string(kind.what) + " that " + std::string(kind.writers) +
                              " wrote";
  std::error_code ec;
  const auto status = fs::symlink_status(dir, ec);
  if (ec || !fs::exists(status)) return {};
  if (!fs::is_directory(status)) {
    return make_error(Error::Kind::bad_input, dir.string(),
                      "exists and is not a directory; refusing to replace it; " + allowed);
  }
  if (fs::is_empty(dir, ec) || ec || written_by_penumbra(dir / kind.marker)) return {};
  return make_error(Error::Kind::bad_input, dir.string(),
                    "is a non-empty directory that is not a penumbra " + std::string(kind.what) +
                        " (no " + std::string(kind.marker) +
                        " whose \"generator\" is penumbra); refusing to replace it; " + allowed);
}

Status check_output_directory(const fs::path& out) {
  return check_replaceable_directory(out, {"library", "index.json", "penumbra build or merge"});
}

}  // namespace penumbra
