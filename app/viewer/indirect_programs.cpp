#include "indirect_programs.h"

#include "gpu_uniforms.h"
#include "shaders.h"

namespace ivis::app {

GlProgram& IndirectPrograms::get(const render::MethodInfo& method)
{
    auto it = mPrograms.find(method.name);
    if (it == mPrograms.end()) {
        const std::string name = "indirect " + method.name;
        GlProgram program(name.c_str(), shaders::fullScreenVertex().c_str(), shaders::indirectFragment(method.name).c_str());
        for (const render::ParameterSpec& spec : method.parameters) {
            const std::string uniform = parameterUniform(spec.key);
            if (glGetUniformLocation(program.id(), uniform.c_str()) < 0)
                throw GlError("the viewer's shader of " + method.name + " reads no uniform " + uniform +
                              " for its parameter " + spec.key + " (assets/shaders/method_" + method.name + ".glsl)");
        }
        it = mPrograms.emplace(method.name, std::move(program)).first;
    }
    return it->second;
}

}  // namespace ivis::app
