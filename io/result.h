// Result<T>: a value, or an error message that names the file, the field and the value.
// What io/ and cli/ return instead of throwing (STYLE rule 5).
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace roomcad {

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit, like std::expected
  static Result failure(std::string message) { return Result(std::nullopt, std::move(message)); }

  [[nodiscard]] bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  [[nodiscard]] const T& value() const& { return *value_; }
  [[nodiscard]] T& value() & { return *value_; }
  [[nodiscard]] T&& value() && { return std::move(*value_); }
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  Result(std::nullopt_t, std::string message) : error_(std::move(message)) {}
  std::optional<T> value_;
  std::string error_;
};

/// A Result with no value: success, or an error message.
struct Status {
  std::string error;  ///< empty on success
  [[nodiscard]] bool ok() const { return error.empty(); }
  explicit operator bool() const { return ok(); }
  static Status success() { return {}; }
  static Status failure(std::string message) { return {std::move(message)}; }
};

}  // namespace roomcad
