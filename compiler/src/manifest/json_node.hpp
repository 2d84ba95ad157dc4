// A JSON value with the place it came from, so every manifest error names the
// file and the JSON path (RFC 6901 pointer) of the offending value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "penumbra/model/json_text.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::manifest_detail {

class JsonNode {
 public:
  // `source` must outlive the node and every node derived from it.
  JsonNode(const nlohmann::json& value, std::string_view source, std::string path = "")
      : value_(&value), source_(source), path_(std::move(path)) {}

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }

  bool has(std::string_view key) const;
  JsonNode member(std::string_view key) const;  // the key must exist
  JsonNode element(std::size_t index) const;

  // The value itself, or its elements when it is an array: every axis takes
  // one value or a list. Errors when the list is empty.
  Result<std::vector<JsonNode>> items() const;

  Status expect_object() const;
  Status expect_array() const;
  // Errors, at the key's own path, on the first key not in `allowed`.
  Status expect_keys(std::span<const std::string_view> allowed) const;
  Result<int> integer() const;
  Result<std::uint64_t> unsigned_integer() const;
  Result<std::string> string() const;
  Result<bool> boolean() const;

  // "file: /json/path", or "file" for the document itself.
  std::string where() const;
  // A bad_input error at this node.
  Error error(std::string message) const;
  // `cause` (which has no location) moved to this node.
  Error error(const Error& cause) const;

 private:
  Error type_error(std::string_view expected) const;

  const nlohmann::json* value_;
  std::string_view source_;
  std::string path_;
};

}  // namespace penumbra::manifest_detail
