/// @file shader_harness.h
/// @brief Runs functions of the viewer's shaders on the GPU (under Xvfb, Mesa's llvmpipe) so that
///        tests compare them with the CPU functions they mirror on the same inputs.
#pragma once

#include <gl_objects.h>

#include <glm/vec4.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ivis::test {

/// @brief A function call of the shaders, run once per item of its inputs.
struct ShaderCall {
    std::string method = "inversevis-wrap";  ///< whose indirect functions (app::shaders::indirectFunctions) it calls
    std::string body;   ///< GLSL statements: read IN(j), write OUT(j) (vec4 each)
    int inputsPerItem = 1;
    int outputsPerItem = 1;
    std::function<void(app::GlProgram&)> setUniforms;  ///< the uniforms the body's functions read (none: unset)
};

/// @brief Runs @a call in a compute shader over @a inputs (call.inputsPerItem vec4 per item).
/// @return call.outputsPerItem vec4 per item
/// @throw app::GlError when the shader does not compile or link
std::vector<glm::vec4> runShaderCall(const ShaderCall& call, const std::vector<glm::vec4>& inputs);

}  // namespace ivis::test
