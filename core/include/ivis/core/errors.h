/// @file errors.h
/// @brief Typed exceptions thrown by the libraries and the always-on invariant check.
/// @note Libraries never call exit(); app/ catches these in main and exits with status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace ivis {

/// @brief Base of the errors a user can fix (programs report them and exit with status 2).
class UserError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief Bad user input (a file, a flag value); the message names the file or value.
class InputError : public UserError {
public:
    using UserError::UserError;
};

/// @brief A value outside its allowed range (a resolution, a parameter).
class ValueError : public UserError {
public:
    using UserError::UserError;
};

/// @brief A long operation was cancelled through its interrupter.
class Cancelled : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// @brief A broken internal invariant: a bug, never bad input.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

/// @brief @a text on one line (line breaks as spaces, trailing white space dropped): another
///        library's message quoted in one of ours, which the programs print as one line.
std::string oneLine(std::string text);

namespace detail {
/// @brief Throws InternalError naming the failed condition and its place.
[[noreturn]] void checkFailed(const char* condition, const char* file, int line);
}  // namespace detail

}  // namespace ivis

/// Always-on invariant check (pbrt's CHECK).
#define IVIS_CHECK(cond) \
    ((cond) ? (void)0 : ::ivis::detail::checkFailed(#cond, __FILE__, __LINE__))

#ifdef NDEBUG
#define IVIS_DCHECK(cond) ((void)0)
#else
#define IVIS_DCHECK(cond) IVIS_CHECK(cond)
#endif
