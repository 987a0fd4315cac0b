#include "indirect_programs.h"

#include "shaders.h"

namespace ivis::app {

GlProgram& IndirectPrograms::get(const std::string& method)
{
    auto it = mPrograms.find(method);
    if (it == mPrograms.end()) {
        const std::string name = "indirect " + method;
        GlProgram program(name.c_str(), shaders::fullScreenVertex().c_str(), shaders::indirectFragment(method).c_str());
        it = mPrograms.emplace(method, std::move(program)).first;
    }
    return it->second;
}

}  // namespace ivis::app
