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
        auto checkReads = [&](const std::string& key, const char* what) {
            const std::string uniform = parameterUniform(key);
            if (glGetUniformLocation(program.id(), uniform.c_str()) < 0)
                throw GlError("the viewer's shader of " + method.name + " reads no uniform " + uniform + " for its " +
                              what + " " + key + " (assets/shaders/method_" + method.name + ".glsl)");
        };
        for (const render::ParameterSpec& spec : method.parameters) checkReads(spec.key, "parameter");
        for (const std::string& key : method.viewValueKeys) checkReads(key, "view value");
        it = mPrograms.emplace(method.name, std::move(program)).first;
    }
    return it->second;
}

}  // namespace ivis::app
