// Result<T>: a value or a typed Error with a one-line reason (vk-bootstrap's style of setup results).
// Every engine function a user, a file or the machine can make fail returns one of these; broken
// internal contracts are assertions instead.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace cetview::engine {

enum class ErrorCode {
  kNoVulkan,          // no Vulkan driver (ICD) could be loaded
  kNoDevice,          // drivers load, but no usable device (Vulkan 1.1, graphics queue) exists
  kDeviceNotFound,    // no device name contains the requested --device substring
  kMissingLayer,      // a requested layer (validation) is not installed
  kMissingExtension,  // a required instance or device extension is missing
  kUnsupported,       // the device lacks a feature the request needs
  kOutOfMemory,       // host or device memory exhausted
  kDeviceLost,        // the device was lost; the renderer must be recreated
  kSurfaceLost,       // the window surface is gone
  kVulkan,            // any other failed Vulkan call
  kInvalidArgument,   // the caller broke a documented precondition (ids, index ranges, sizes)
  kIo,                // reading or writing a file failed
};

struct Error {
  ErrorCode code = ErrorCode::kVulkan;
  std::string message;  // one line, no trailing newline
};

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}      // NOLINT: implicit, so `return value;` works
  Result(Error error) : state_(std::move(error)) {}  // NOLINT: implicit, so `return error;` works

  bool ok() const { return state_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & {
    assert(ok());
    return std::get<0>(state_);
  }
  const T& value() const& {
    assert(ok());
    return std::get<0>(state_);
  }
  T&& value() && {
    assert(ok());
    return std::get<0>(std::move(state_));
  }
  T& operator*() & { return value(); }
  T&& operator*() && { return std::move(*this).value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

  const Error& error() const {
    assert(!ok());
    return std::get<1>(state_);
  }

 private:
  std::variant<T, Error> state_;
};

template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)) {}  // NOLINT: implicit, so `return error;` works

  bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }
  const Error& error() const {
    assert(!ok());
    return *error_;
  }

 private:
  std::optional<Error> error_;
};

using Status = Result<void>;

inline Error makeError(ErrorCode code, std::string message) {
  return Error{code, std::move(message)};
}

}  // namespace cetview::engine

// Propagates a failed Status/Result from an expression to the caller (whose return type is any Result).
#define CETVIEW_TRY(expr)                                              \
  do {                                                                 \
    auto&& cetview_try_result_ = (expr);                               \
    if (!cetview_try_result_.ok()) return cetview_try_result_.error(); \
  } while (0)
