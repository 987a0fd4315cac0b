/// @file log.h
/// @brief Minimal leveled logging to stderr, shared by the libraries and the programs.
/// @warning Thread-safe: each message is written whole under a lock.
#pragma once

#include <functional>
#include <string>

namespace ivis::core {

/// @brief Message importance; messages below the current level are dropped.
enum class LogLevel { Info = 1, Warning = 2, Error = 3, Silent = 4 };

/// @brief Sets the minimum level printed (default Info).
void setLogLevel(LogLevel level);

/// @brief Current minimum level.
LogLevel logLevel();

/// @brief Sets the log level for its life and puts the previous one back (a pass that reads what
///        a later pass reads again, and says, stays silent).
class ScopedLogLevel {
public:
    /// @brief Sets @a level until this object goes.
    explicit ScopedLogLevel(LogLevel level) : mPrevious(logLevel()) { setLogLevel(level); }
    ~ScopedLogLevel() { setLogLevel(mPrevious); }
    ScopedLogLevel(const ScopedLogLevel&) = delete;
    ScopedLogLevel& operator=(const ScopedLogLevel&) = delete;

private:
    LogLevel mPrevious;
};

/// @brief Sets the program named before each message ("inversevis" unless set).
void setLogProgram(const std::string& name);

/// @brief What takes the messages instead of stderr: their level and text (without the program's
///        name); Python's module says them in Python. Called under the log's lock, from any thread.
using LogSink = std::function<void(LogLevel level, const std::string& message)>;

/// @brief Sends every message to @a sink instead of stderr (an empty sink: stderr again).
void setLogSink(LogSink sink);

/// @brief Prints "<program>: <message>" when Info is enabled.
void logInfo(const std::string& message);

/// @brief Prints "<program>: warning: <message>" when Warning is enabled.
void logWarning(const std::string& message);


}  // namespace ivis::core
