// Result<T>: the one value-or-error type used across Penumbra.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace penumbra {

// What went wrong and where. `where` names the file, JSON path, argument,
// variant/target or Vulkan call; `message` says what is wrong and what is allowed.
struct Error {
  enum class Kind {
    bad_input,  // user input is malformed or out of range (CLI exit code 2)
    compile,    // a shader failed to compile, validate or cross-compile (exit 2)
    device,     // no usable Vulkan device or a Vulkan call failed (exit 2)
    io,         // a file could not be read or written (exit 2)
    internal,   // a bug in Penumbra
  };
  Kind kind = Kind::bad_input;
  std::string where;
  std::string message;

  // "where: message", or just the message when there is no location.
  std::string to_string() const { return where.empty() ? message : where + ": " + message; }
};

inline Error make_error(Error::Kind kind, std::string where, std::string message) {
  return Error{kind, std::move(where), std::move(message)};
}

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : data_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
  Result(Error error) : data_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  bool ok() const { return data_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & { return std::get<0>(data_); }
  const T& value() const& { return std::get<0>(data_); }
  T&& value() && { return std::get<0>(std::move(data_)); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  const Error& error() const { return std::get<1>(data_); }

 private:
  std::variant<T, Error> data_;
};

// Result<void>: success or an Error.
template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }
  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

using Status = Result<void>;

}  // namespace penumbra

// Propagates an error from an expression yielding Result<...>.
#define PENUMBRA_TRY(expr)                                         \
  do {                                                             \
    if (auto penumbra_try_status_ = (expr); !penumbra_try_status_) \
      return penumbra_try_status_.error();                         \
  } while (0)

// Assigns the value of an expression yielding Result<T> to `lhs` (an
// existing variable or member), or propagates its error.
#define PENUMBRA_TRY_ASSIGN(lhs, expr) \
  PENUMBRA_TRY_ASSIGN_IMPL(PENUMBRA_TRY_CONCAT(penumbra_try_result_, __LINE__), lhs, expr)
#define PENUMBRA_TRY_ASSIGN_IMPL(tmp, lhs, expr) \
  auto tmp = (expr);                             \
  if (!tmp) return tmp.error();                  \
  lhs = std::move(*tmp)
#define PENUMBRA_TRY_CONCAT(a, b) PENUMBRA_TRY_CONCAT_IMPL(a, b)
#define PENUMBRA_TRY_CONCAT_IMPL(a, b) a##b
