// Result<T>: the value of an operation on outside input (files, glTF, images, shaders, project
// files), or the Error that says which file and what went wrong. A small C++20 stand-in for
// C++23 std::expected; we do not use exceptions (STYLE.md §4).
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace grass {

struct Error {
    std::string path;     // the file, option or JSON path at fault; may be empty
    std::string message;  // what is wrong and, where we know it, how to fix it

    // "path: message", the one line the CLI prints on stderr.
    std::string str() const { return path.empty() ? message : path + ": " + message; }
    bool operator==(const Error&) const = default;
};

inline Error makeError(std::string path, std::string message) {
    return Error{std::move(path), std::move(message)};
}

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : mState(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : mState(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return mState.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(mState); }
    const T& value() const& { return std::get<0>(mState); }
    T&& value() && { return std::get<0>(std::move(mState)); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    const Error& error() const { return std::get<1>(mState); }

private:
    std::variant<T, Error> mState;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : mError(std::move(error)), mOk(false) {}

    bool ok() const { return mOk; }
    explicit operator bool() const { return ok(); }
    const Error& error() const { return mError; }

private:
    Error mError;
    bool mOk = true;
};

}  // namespace grass
