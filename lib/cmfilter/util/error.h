// SPDX-License-Identifier: Apache-2.0
// Typed errors for libcmfilter: every fallible library call returns Expected<T>,
// which holds either a value or an Error whose kind maps onto one CLI exit code
// (docs/exit-codes.md). No exceptions cross the library boundary.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace cmfilter {

enum class ErrorKind {
    Usage = 1,     // malformed command line (the CLI's own errors)
    Io = 2,        // a file cannot be opened, read or written
    BadInput = 3,  // a file or value is readable but invalid
    Runtime = 4,   // an internal or library failure
};

// An error about an option names it in `message` by the options struct's
// field, qualified ("ApplyOptions::lod -1 is invalid ..."), and records that
// name in `field`: a front end may replace the name in the message with its
// own for the option (the CLI: its flag, docs/exit-codes.md). A message may
// name more fields than the one recorded (the first it names, or the one
// whose value is wrong). Messages that name no option leave `field` empty.
struct Error {
    ErrorKind kind = ErrorKind::Runtime;
    std::string message;
    std::string field;

    Error() = default;
    Error(ErrorKind kind_, std::string message_, std::string field_ = {})
        : kind(kind_), message(std::move(message_)), field(std::move(field_))
    {
    }
};

inline Error io_error(std::string message, std::string field = {})
{
    return {ErrorKind::Io, std::move(message), std::move(field)};
}
inline Error bad_input(std::string message, std::string field = {})
{
    return {ErrorKind::BadInput, std::move(message), std::move(field)};
}
inline Error runtime_error(std::string message) { return {ErrorKind::Runtime, std::move(message), {}}; }

// The same error with `prefix` (where it happened) before its message.
inline Error prefixed(const std::string& prefix, const Error& e) { return {e.kind, prefix + e.message, e.field}; }

// A value or an Error. Minimal by design: construct from either, test with
// has_value()/operator bool, read with value()/error().
template <typename T>
class Expected {
public:
    Expected(T value) : data_(std::in_place_index<0>, std::move(value)) {}
    Expected(Error error) : data_(std::in_place_index<1>, std::move(error)) {}

    bool has_value() const { return data_.index() == 0; }
    explicit operator bool() const { return has_value(); }

    T& value() &
    {
        assert(has_value());
        return std::get<0>(data_);
    }
    const T& value() const&
    {
        assert(has_value());
        return std::get<0>(data_);
    }
    T&& value() &&
    {
        assert(has_value());
        return std::get<0>(std::move(data_));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const
    {
        assert(!has_value());
        return std::get<1>(data_);
    }

private:
    std::variant<T, Error> data_;
};

// For calls that return nothing but may fail.
struct Unit {};
using Status = Expected<Unit>;
inline Status ok() { return Unit{}; }

}  // namespace cmfilter
