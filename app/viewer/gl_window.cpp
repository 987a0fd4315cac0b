#include "gl_window.h"

#include "gl_objects.h"

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdint>
#include <vector>

namespace ivis::app {
namespace {

std::string gLastGlfwError;

void onGlfwError(int code, const char* description)
{
    gLastGlfwError = std::string(description ? description : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

}  // namespace

void initGlfw()
{
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throw GlError("cannot open a window: " + gLastGlfwError + " (no display? headless use: xvfb-run -a ...)");
}

GLFWwindow* createGlWindow(const std::string& title, int width, int height, bool visible)
{
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window) throw GlError("OpenGL 4.3 core profile is not available: " + gLastGlfwError);
    glfwMakeContextCurrent(window);
    if (epoxy_gl_version() < 43) {
        const int version = epoxy_gl_version();
        glfwDestroyWindow(window);
        throw GlError("OpenGL 4.3 core profile is not available (the context reports " + std::to_string(version / 10) +
                      "." + std::to_string(version % 10) + ")");
    }
    return window;
}

std::string glRendererName()
{
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

bool isSoftwareGl(const std::string& rendererName)
{
    for (const char* software : {"llvmpipe", "softpipe", "swrast"})
        if (rendererName.find(software) != std::string::npos) return true;
    return false;
}

void startImGui(GLFWwindow* window)
{
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 430 core");
}

void stopImGui()
{
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

core::Image readWindow(GLFWwindow* window)
{
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    std::vector<std::uint8_t> bytes(std::size_t(width) * height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    checkGl("reading the window back");
    core::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* p = bytes.data() + (std::size_t(height - 1 - y) * width + x) * 4;
            image.at(x, y) = glm::vec4(core::linearFromSrgb(p[0] / 255.0f), core::linearFromSrgb(p[1] / 255.0f),
                                       core::linearFromSrgb(p[2] / 255.0f), 1.0f);
        }
    return image;
}

}  // namespace ivis::app
