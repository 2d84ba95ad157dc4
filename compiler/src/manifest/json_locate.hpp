// Where in a JSON text a value lies, for messages that point at it
// (FILE:LINE:COL).
#pragma once

#include <optional>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::manifest_detail {

struct TextPosition {
  int line = 1;    // 1-based
  int column = 1;  // 1-based, in bytes
};

// The line and column of byte `offset` of `text`.
TextPosition position_of(std::string_view text, std::size_t offset);

// The position of the value at RFC 6901 `pointer` ("" is the document) in
// the JSON `text`; nullopt when the text is malformed or has no such value.
std::optional<TextPosition> locate_pointer(std::string_view text, std::string_view pointer);

// Points `error` about the manifest `source` (whose text is `text`) at the
// line and column of the value its JSON path names, or of a JSON syntax
// error, as compilers do: its `where` "FILE: /json/path" becomes
// "FILE:LINE:COL: /json/path" (and "FILE" "FILE:LINE:COL"). Leaves it as it
// is when no place is found.
void add_position(Error& error, std::string_view text, std::string_view source);

}  // namespace penumbra::manifest_detail
