/// @file viewer_clock.h
/// @brief The viewer's clock: now, and the time a piece of work takes.
#pragma once

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#include <GLFW/glfw3.h>

#include <chrono>

namespace ivis::app {

/// @brief Seconds since GLFW started (the window's clock: camera moves, playing, jobs).
inline double now() { return glfwGetTime(); }

/// @brief Milliseconds taken by @a work, waiting for the GPU to finish.
template <typename Work>
double timedMs(Work&& work)
{
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// @brief Seconds since @a start.
inline double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ivis::app
