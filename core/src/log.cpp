#include <ivis/core/log.h>

#include <atomic>
#include <iostream>
#include <mutex>

namespace ivis::core {
namespace {
std::atomic<LogLevel> gLevel{LogLevel::Info};
std::mutex gMutex;
std::string gProgram = "inversevis";  // guarded by gMutex
LogSink gSink;                         // guarded by gMutex

void emit(LogLevel level, const char* tag, const std::string& message)
{
    if (level < gLevel.load()) return;
    std::lock_guard<std::mutex> lock(gMutex);
    if (gSink) gSink(level, message);
    else std::cerr << gProgram << ": " << tag << message << '\n';
}
}  // namespace

void setLogSink(LogSink sink)
{
    std::lock_guard<std::mutex> lock(gMutex);
    gSink = std::move(sink);
}

void setLogProgram(const std::string& name)
{
    std::lock_guard<std::mutex> lock(gMutex);
    gProgram = name;
}

void setLogLevel(LogLevel level) { gLevel = level; }
LogLevel logLevel() { return gLevel.load(); }
void logInfo(const std::string& message) { emit(LogLevel::Info, "", message); }
void logWarning(const std::string& message) { emit(LogLevel::Warning, "warning: ", message); }

}  // namespace ivis::core
