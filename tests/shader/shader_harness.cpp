// The compute pass of the shader tests, and their main: a hidden GLFW window's OpenGL 4.3 context
// for the whole run.
#include "shader_harness.h"

#include <gl_window.h>
#include <shaders.h>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cstring>
#include <exception>
#include <iostream>

#if defined(__SANITIZE_ADDRESS__)
// Under `scripts/test.sh --sanitize`: Mesa's GL driver keeps allocations no suppression can name
// (as app/viewer/main.cpp says); the other checks stay on.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif

namespace ivis::test {
namespace {

constexpr int kGroupSize = 64;
constexpr GLuint kInputBinding = 6, kOutputBinding = 7;  // after the mesh's (0-3) and the methods' (4-5)
static_assert(app::shaders::kFirstMethodBuffer + app::shaders::kMaxMethodBuffers <= int(kInputBinding),
              "the harness's buffers must follow the methods' vertex arrays");

/// The compute shader: the method's indirect functions, then a main that runs @a call per item.
std::string computeSource(const ShaderCall& call)
{
    return app::shaders::indirectFunctions(call.method) +
           "layout(local_size_x = " + std::to_string(kGroupSize) + ") in;\n"
           "layout(std430, binding = " + std::to_string(kInputBinding) + ") readonly buffer HarnessInputs { vec4 harnessIn[]; };\n"
           "layout(std430, binding = " + std::to_string(kOutputBinding) + ") writeonly buffer HarnessOutputs { vec4 harnessOut[]; };\n"
           "uniform int uHarnessItems;\n"
           "#define IN(j) harnessIn[item * " + std::to_string(call.inputsPerItem) + "u + uint(j)]\n"
           "#define OUT(j) harnessOut[item * " + std::to_string(call.outputsPerItem) + "u + uint(j)]\n"
           "void main()\n{\n"
           "    uint item = gl_GlobalInvocationID.x;\n"
           "    if (item >= uint(uHarnessItems)) return;\n" +
           call.body + "\n}\n";
}

}  // namespace

std::vector<glm::vec4> runShaderCall(const ShaderCall& call, const std::vector<glm::vec4>& inputs)
{
    const std::size_t items = inputs.size() / std::size_t(call.inputsPerItem);
    app::GlProgram program("shader test", computeSource(call).c_str());
    program.set("uHarnessItems", int(items));
    if (call.setUniforms) call.setUniforms(program);

    app::GlBuffer input(app::newName(glGenBuffers)), output(app::newName(glGenBuffers));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, input.id());
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(inputs.size() * sizeof(glm::vec4)), inputs.data(), GL_STATIC_DRAW);
    std::vector<glm::vec4> outputs(items * std::size_t(call.outputsPerItem), glm::vec4(-12345.0f));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, output.id());
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(outputs.size() * sizeof(glm::vec4)), outputs.data(), GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInputBinding, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutputBinding, output.id());

    glUseProgram(program.id());
    glDispatchCompute(GLuint((items + kGroupSize - 1) / kGroupSize), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, output.id());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(outputs.size() * sizeof(glm::vec4)), outputs.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glUseProgram(0);
    app::checkGl("running a shader test");
    return outputs;
}

}  // namespace ivis::test

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    try {
        ivis::app::initGlfw();
        GLFWwindow* window = ivis::app::createGlWindow("shader tests", 64, 64, false);
        std::cout << "OpenGL: " << ivis::app::glRendererName() << "\n";
        const int status = RUN_ALL_TESTS();
        glfwDestroyWindow(window);
        glfwTerminate();
        return status;
    } catch (const std::exception& error) {
        std::cerr << "shader tests: " << error.what() << "\n";
        return 1;
    }
}
