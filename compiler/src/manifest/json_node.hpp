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

#include "penumbra/support/result.hpp"

namespace penumbra::manifest_detail {

// A value for a message: a scalar as written (16.5 reads as 16.5), shortened;
// a container by kind ("an object", "an array").
std::string describe_json(const nlohmann::json& value);

// nlohmann's what() without its "[json.exception.type_error.302] " tag, any
// quoted input shortened.
std::string json_exception_text(const nlohmann::json::exception& e);

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
