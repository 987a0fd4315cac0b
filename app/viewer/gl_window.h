/// @file gl_window.h
/// @brief The viewer's GLFW window with its OpenGL 4.3 core context, Dear ImGui on it, and reading
///        the window back.
/// @note Call from the main thread only (GLFW's rule).
#pragma once

#include <ivis/core/image.h>

#include <string>

struct GLFWwindow;

namespace ivis::app {

/// @brief glfwInit with an error callback that keeps GLFW's last message for the errors below.
/// @throw GlError when GLFW cannot start (no display)
void initGlfw();

/// @brief Creates a window with an OpenGL 4.3 core context and makes the context current.
/// @param visible false for headless use (the window is never shown)
/// @throw GlError when no such context can be had (the window is then destroyed)
GLFWwindow* createGlWindow(const std::string& title, int width, int height, bool visible);

/// @brief "<GL_RENDERER>, OpenGL <GL_VERSION>" of the current context.
std::string glRendererName();

/// @brief True when @a rendererName (glRendererName) is a software rasteriser (Mesa's llvmpipe,
///        softpipe or swrast), which runs the shaders on the CPU.
bool isSoftwareGl(const std::string& rendererName);

/// @brief Creates the ImGui context with its GLFW and OpenGL 3 backends on @a window.
void startImGui(GLFWwindow* window);

/// @brief Shuts the backends down and destroys the ImGui context.
void stopImGui();

/// @brief The window's back buffer as a linear image, row 0 at the top.
/// @throw GlError when it cannot be read
core::Image readWindow(GLFWwindow* window);

}  // namespace ivis::app
