// JSON values and nlohmann's errors as the project's messages quote them:
// every reader of a JSON file (manifests, index.json) words them alike.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace penumbra {

// A value for a message: a scalar as written (16.5 reads as 16.5), shortened;
// a container by kind ("an object", "an array").
std::string describe_json(const nlohmann::json& value);

// nlohmann's what() without its "[json.exception.type_error.302] " tag, any
// quoted input shortened.
std::string json_exception_text(const nlohmann::json::exception& e);

}  // namespace penumbra
