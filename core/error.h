// SPDX-License-Identifier: GPL-3.0-or-later
// Errors as values: what a failure says (a Code, a message, where), carried by Status and
// Result<T>; and the one exception modeling throws, PreconditionError, carrying the same.
//
// The rule (docs/STYLE of the repository, after Manifold's Status()): readers, writers and
// commands return Result/Status and never throw for bad input; modeling throws
// PreconditionError when a documented precondition does not hold; what can never happen is an
// RC_ASSERT (core/assert.h). Messages name the file, the object or field, and the value.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "core/code.h"

namespace roomcad {

/// Where a problem sits in a file: line and column count from 1 (0: unknown), `pointer` is a
/// JSON pointer ("/walls/3/thickness") or empty.
struct Location {
  std::string file;
  std::string pointer;
  std::size_t line = 0;
  std::size_t column = 0;
  friend bool operator==(const Location&, const Location&) = default;
};

/// One failure: its code, one sentence a person can act on, and where, if known.
struct Error {
  Error() = default;
  Error(Code code, std::string message, std::optional<Location> location = std::nullopt)
      : code(code), message(std::move(message)), location(std::move(location)) {}

  Code code = Code::internal;
  std::string message;
  std::optional<Location> location;
  friend bool operator==(const Error&, const Error&) = default;
};

/// Writes "code: message" (and the location, if known): errors print readably in test failures.
std::ostream& operator<<(std::ostream& out, const Error& error);

/// Success, or an Error. `if (!status) ... status.error()`.
class [[nodiscard]] Status {
 public:
  Status() = default;                                ///< success
  Status(Error error) : error_(std::move(error)) {}  // NOLINT: implicit, as std::unexpected
  static Status success() { return {}; }
  static Status failure(Code code, std::string message, std::optional<Location> at = {}) {
    return Error{code, std::move(message), std::move(at)};
  }

  [[nodiscard]] bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }
  /// @pre !ok()
  [[nodiscard]] const Error& error() const { return *error_; }
  [[nodiscard]] Code code() const { return error_ ? error_->code : Code::internal; }
  [[nodiscard]] const std::string& message() const { return error_->message; }

 private:
  std::optional<Error> error_;
};

/// A value, or the Error that kept it from being made.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}      // NOLINT: implicit, like std::expected
  Result(Error error) : error_(std::move(error)) {}  // NOLINT
  static Result failure(Code code, std::string message, std::optional<Location> at = {}) {
    return Error{code, std::move(message), std::move(at)};
  }

  [[nodiscard]] bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  /// @pre ok()
  [[nodiscard]] const T& value() const& { return *value_; }
  [[nodiscard]] T& value() & { return *value_; }
  [[nodiscard]] T&& value() && { return std::move(*value_); }
  const T& operator*() const& { return *value_; }
  T& operator*() & { return *value_; }
  const T* operator->() const { return &*value_; }
  T* operator->() { return &*value_; }
  /// @pre !ok()
  [[nodiscard]] const Error& error() const { return *error_; }
  [[nodiscard]] Code code() const { return error_ ? error_->code : Code::internal; }
  [[nodiscard]] const std::string& message() const { return error_->message; }
  /// @return the failure as a Status (success when ok()).
  [[nodiscard]] Status status() const { return ok() ? Status() : Status(*error_); }

 private:
  std::optional<T> value_;
  std::optional<Error> error_;
};

/// Thrown by modeling (and the other libraries' computing functions) when a documented
/// precondition does not hold; what() is the message, which names the function, the object id,
/// the failed check and the values (STYLE rule 6). Commands turn it into their exit status.
class PreconditionError : public std::runtime_error {
 public:
  explicit PreconditionError(std::string message, Code code = Code::precondition)
      : std::runtime_error(message), error_{code, std::move(message), std::nullopt} {}
  explicit PreconditionError(Error error)
      : std::runtime_error(error.message), error_(std::move(error)) {}
  [[nodiscard]] const Error& error() const { return error_; }
  [[nodiscard]] Code code() const { return error_.code; }

 private:
  Error error_;
};

/// Throws PreconditionError with `status`'s code and its message prefixed by "`function`: ",
/// unless `status` is ok: how a function that also exposes its check enforces it.
inline void throw_if_failed(const Status& status, std::string_view function) {
  if (status) return;
  Error error = status.error();
  error.message = std::string(function) + ": " + error.message;
  throw PreconditionError(std::move(error));
}

}  // namespace roomcad
