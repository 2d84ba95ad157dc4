#include "manifest/json_node.hpp"

#include <limits>

#include "penumbra/support/text.hpp"

namespace penumbra::manifest_detail {
namespace {

// RFC 6901: '~' and '/' inside a key are written as ~0 and ~1.
std::string escape_pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

bool JsonNode::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

JsonNode JsonNode::member(std::string_view key) const {
  return {value_->at(std::string(key)), source_, path_ + "/" + escape_pointer_token(key)};
}

JsonNode JsonNode::element(std::size_t index) const {
  return {value_->at(index), source_, path_ + "/" + std::to_string(index)};
}

Result<std::vector<JsonNode>> JsonNode::items() const {
  if (!value_->is_array()) return std::vector<JsonNode>{*this};
  if (value_->empty()) return error("expected at least one value, got an empty list");
  std::vector<JsonNode> out;
  for (std::size_t i = 0; i < value_->size(); ++i) out.push_back(element(i));
  return out;
}

Status JsonNode::expect_object() const {
  if (value_->is_object()) return {};
  return type_error("an object");
}

Status JsonNode::expect_array() const {
  if (value_->is_array()) return {};
  return type_error("an array");
}

Status JsonNode::expect_keys(std::span<const std::string_view> allowed) const {
  PENUMBRA_TRY(expect_object());
  for (const auto& [key, unused] : value_->items()) {
    bool known = false;
    for (std::string_view name : allowed) known = known || name == key;
    if (!known) {
      return member(key).error("unknown key '" + shorten(key) +
                               "'; allowed keys: " + join(allowed, ", "));
    }
  }
  return {};
}

Result<int> JsonNode::integer() const {
  if (!value_->is_number_integer()) return type_error("an integer");
  if (value_->is_number_unsigned()) {
    if (value_->get<std::uint64_t>() >
        static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      return error("integer " + shorten(value_->dump()) + " is too large");
    }
    return static_cast<int>(value_->get<std::uint64_t>());
  }
  if (value_->get<std::int64_t>() < std::numeric_limits<int>::min()) {
    return error("integer " + shorten(value_->dump()) + " is too small");
  }
  return static_cast<int>(value_->get<std::int64_t>());
}

Result<std::uint64_t> JsonNode::unsigned_integer() const {
  if (!value_->is_number_unsigned()) return type_error("an integer in 0..18446744073709551615");
  return value_->get<std::uint64_t>();
}

Result<std::string> JsonNode::string() const {
  if (!value_->is_string()) return type_error("a string");
  return value_->get<std::string>();
}

Result<bool> JsonNode::boolean() const {
  if (!value_->is_boolean()) return type_error("true or false");
  return value_->get<bool>();
}

std::string JsonNode::where() const {
  std::string out(source_);
  if (!path_.empty()) out += ": " + path_;
  return out;
}

Error JsonNode::error(std::string message) const {
  return make_error(Error::Kind::bad_input, where(), std::move(message));
}

Error JsonNode::error(const Error& cause) const {
  return make_error(cause.kind, where(), cause.message);
}

Error JsonNode::type_error(std::string_view expected) const {
  return error("expected " + std::string(expected) + ", got " + describe_json(*value_));
}

}  // namespace penumbra::manifest_detail
