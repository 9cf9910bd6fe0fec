// Error reporting for every retroaa entry point: a Status or a Result<T> naming the cause.
// Nothing in retroaa throws across its API, and nothing aborts the host.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace retroaa {

enum class ErrorCode {
  Ok = 0,
  InvalidConfig,          // a config key or value is unknown or out of range (message names it)
  InvalidLayout,          // the GBufferLayout is inconsistent (missing role, bad format, zero size)
  UnsupportedContext,     // the GL context lacks something retroaa needs and no fallback exists
  IncompleteFramebuffer,  // a framebuffer retroaa built is incomplete (message has the status)
  ShaderError,            // a built-in shader failed to compile (overrides fall back instead)
  WrongCallOrder,         // e.g. shade() before resolve() in a frame
};

struct Error {
  ErrorCode code = ErrorCode::Ok;
  std::string message;
};

class Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)) {}  // NOLINT: implicit from an error
  static Status ok() { return {}; }
  bool isOk() const { return error_.code == ErrorCode::Ok; }
  explicit operator bool() const { return isOk(); }
  const Error& error() const { return error_; }

 private:
  Error error_;
};

template <typename T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}      // NOLINT: implicit from a value
  Result(Error error) : error_(std::move(error)) {}  // NOLINT: implicit from an error
  bool isOk() const { return value_.has_value(); }
  explicit operator bool() const { return isOk(); }
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  T* operator->() { return &*value_; }
  const Error& error() const { return error_; }

 private:
  std::optional<T> value_;
  Error error_;
};

}  // namespace retroaa
