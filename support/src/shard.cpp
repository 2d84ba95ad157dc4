// Strict parsing: a typo in a CI matrix ("1/", "01/4", "2 /4") must fail the
// job, not quietly run another slice or the whole job.
#include "penumbra/support/shard.hpp"

#include <charconv>

namespace penumbra {
namespace {

// A decimal number without sign, leading zero or trailing characters.
bool parse_number(std::string_view text, int& value) {
  if (text.empty() || text.size() > 9 || text[0] < '1' || text[0] > '9') return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

Result<Shard> parse_shard(std::string_view text, const std::string& argument) {
  const std::string where = argument + " " + std::string(text);
  const std::size_t slash = text.find('/');
  Shard shard;
  if (slash == std::string_view::npos || !parse_number(text.substr(0, slash), shard.index) ||
      !parse_number(text.substr(slash + 1), shard.count)) {
    return make_error(Error::Kind::bad_input, where,
                      "expected I/N, two whole numbers with 1 <= I <= N (e.g. 2/4)");
  }
  if (shard.index > shard.count) {
    return make_error(Error::Kind::bad_input, where,
                      "I must be in 1..N (1.." + std::to_string(shard.count) + ")");
  }
  return shard;
}

std::string to_string(Shard shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

}  // namespace penumbra
