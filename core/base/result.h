// SPDX-License-Identifier: GPL-3.0-or-later
// core/base/: what every part of the core uses: Result/Status errors, progress callbacks,
// the thread helpers, sRGB conversion, text helpers.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace core {

/** What kind of failure an Error is, for callers that react differently (not for the user). */
enum class ErrorKind {
    Failed,      // anything else
    Cancelled,   // the user (or a caller's progress function) asked to stop
    BadInput,    // a file or a value that is not what it should be
    Io,          // reading or writing failed (missing file, permissions, full disk)
    Unsupported, // valid, but not something this build handles
};

/** An error message for the user: names the file (if any) and the problem; and its kind. */
struct Error {
    std::string message;
    ErrorKind kind = ErrorKind::Failed;
};

/** The Error of an operation that the user (or a caller's progress function) stopped. */
inline Error cancelledError(std::string message = "cancelled") {
    return Error{std::move(message), ErrorKind::Cancelled};
}

/** The Error of a file or a value that is not what it should be. */
inline Error badInput(std::string message) {
    return Error{std::move(message), ErrorKind::BadInput};
}

/** A value or an Error. Core functions return this instead of throwing. */
template <typename T> class Result {
public:
    Result(T value) : m_value(std::move(value)) {}
    Result(Error error) : m_error(std::move(error.message)), m_kind(error.kind) {}

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }

    T& value() & {
        assert(ok());
        return *m_value;
    }
    const T& value() const& {
        assert(ok());
        return *m_value;
    }
    T&& value() && {
        assert(ok());
        return std::move(*m_value);
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    /** The error message; empty when ok(). */
    const std::string& error() const { return m_error; }
    /** The error's kind; meaningless when ok(). */
    ErrorKind errorKind() const { return m_kind; }
    /** The error as an Error (to pass it on, e.g. with another message). */
    Error takeError() const { return Error{m_error, m_kind}; }
    bool cancelled() const { return !ok() && m_kind == ErrorKind::Cancelled; }

private:
    std::optional<T> m_value;
    std::string m_error;
    ErrorKind m_kind = ErrorKind::Failed;
};

/** Result for operations without a value. */
class Status {
public:
    Status() = default;
    Status(Error error) : m_error(std::move(error.message)), m_kind(error.kind), m_failed(true) {}
    static Status success() { return {}; }

    bool ok() const { return !m_failed; }
    explicit operator bool() const { return ok(); }
    const std::string& error() const { return m_error; }
    ErrorKind errorKind() const { return m_kind; }
    Error takeError() const { return Error{m_error, m_kind}; }
    bool cancelled() const { return m_failed && m_kind == ErrorKind::Cancelled; }

private:
    std::string m_error;
    ErrorKind m_kind = ErrorKind::Failed;
    bool m_failed = false;
};

} // namespace core
